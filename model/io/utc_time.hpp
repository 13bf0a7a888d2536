// The time stamps our files carry (a session's creation, a calibration's, each answer of a study):
// UTC as ISO 8601 to the second, one spelling everywhere.
#pragma once

#include <string>
#include <string_view>

namespace nibrig::model::io {

// Now, as "2026-11-26T04:01:02Z".
std::string now_utc_iso8601();

// True for a time stamp spelled as now_utc_iso8601 spells it, naming a real instant (month 1-12,
// the month's days, 00:00:00 to 23:59:60) from the year 2000 to 2999.
bool is_utc_iso8601(std::string_view text);

}  // namespace nibrig::model::io
