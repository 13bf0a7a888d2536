#include "model/io/utc_time.hpp"

#include <gtest/gtest.h>

namespace nibrig::model::io {
namespace {

TEST(UtcTime, NowIsSpelledTheWayItIsChecked) { EXPECT_TRUE(is_utc_iso8601(now_utc_iso8601())); }

TEST(UtcTime, OnlyRealInstantsInTheOneSpellingPass) {
  for (const char* good : {"2026-11-26T04:01:02Z", "2028-02-29T23:59:59Z", "2016-12-31T23:59:60Z"})
    EXPECT_TRUE(is_utc_iso8601(good)) << good;
  for (const char* bad :
       {"yesterday", "", "2026-11-26 04:01:02Z", "2026-11-26T04:01:02", "2026-11-26T04:01:02+01:00",
        "2026-02-29T00:00:00Z", "2026-13-01T00:00:00Z", "2026-00-10T00:00:00Z",
        "2026-04-31T00:00:00Z", "2026-11-26T24:00:00Z", "2026-11-26T04:60:00Z",
        "1999-12-31T23:59:59Z", "2026-11-26T04:01:0xZ", "2100-02-29T00:00:00Z"})
    EXPECT_FALSE(is_utc_iso8601(bad)) << bad;
}

}  // namespace
}  // namespace nibrig::model::io
