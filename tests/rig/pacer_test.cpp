// A rig's pacing is real time times a speed-up that a clock can keep: 0 (unpaced) or 0.01 to 1e6.
// A speed-up of 1e-320 would make a capture wait forever.
#include "rig/pacer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace nibrig::rig {
namespace {

TEST(Pacer, ASpeedUpNoClockKeepsIsRefused) {
  for (const double ok : {0.0, Pacer::kMinSpeedup, 1.0, 250.0, Pacer::kMaxSpeedup})
    EXPECT_NO_THROW(Pacer(ok, 1000.0)) << ok;
  for (const double bad : {1e-320, 1e-6, 0.009, -1.0, 2e6, std::numeric_limits<double>::infinity(),
                           std::nan("")}) {
    try {
      Pacer(bad, 1000.0);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("speed-up"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace nibrig::rig
