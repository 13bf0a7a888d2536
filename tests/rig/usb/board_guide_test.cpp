// rig/HARDWARE.md against the firmware and the board model: every failure mode it lists names a test
// of this suite that exists, and every figure it gives that the firmware or the board determine is
// measured here on the simulated board (the fault tests take their bounds from the guide itself).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>
#include <string>

#include "tests/rig/usb/board_host.hpp"
#include "tests/rig/usb/hardware_guide.hpp"

namespace nibrig::rig::usb::testing {
namespace {

// "FirstBuilds/BoardMiswired" and "Name/encoder_reversed_at_17" as the guide names them:
// "BoardMiswired.Name".
std::string guide_test_name(const ::testing::TestInfo& info) {
  std::string suite = info.test_suite_name(), name = info.name();
  if (const auto slash = suite.find('/'); slash != std::string::npos) suite = suite.substr(slash + 1);
  if (const auto slash = name.find('/'); slash != std::string::npos) name = name.substr(0, slash);
  return suite + "." + name;
}

TEST(BoardGuide, EveryFailureModeNamesATestOfThisSuite) {
  std::set<std::string> tests;
  const ::testing::UnitTest& unit = *::testing::UnitTest::GetInstance();
  for (int s = 0; s < unit.total_test_suite_count(); ++s) {
    const ::testing::TestSuite& suite = *unit.GetTestSuite(s);
    for (int t = 0; t < suite.total_test_count(); ++t) tests.insert(guide_test_name(*suite.GetTestInfo(t)));
  }
  const auto modes = hardware_guide_failure_modes();
  // The list: wiring, the disc, the cells, the host at any point, the controller's supply
  // and memory, the bootloader, calibration.
  EXPECT_GE(modes.size(), 20u);
  for (const GuideFailureMode& m : modes) {
    EXPECT_TRUE(tests.count(m.test)) << "'" << m.fault << "' names " << m.test << ", which this suite lacks";
  }
  for (const GuideFigure& f : hardware_guide_figures()) {
    EXPECT_TRUE(tests.count(f.test)) << "'" << f.figure << "' names " << f.test << ", which this suite lacks";
  }
}

// The ADC runs free at 104 us a conversion through normal, tangential, normal, tangential, current:
// two fifths of its conversions are each force channel's. The guide's figure to within 5 %: the
// frame boundaries fall at other phases of the sequence from frame to frame.
TEST(BoardGuideFigures, AdcConversionsPerForceChannelPerFrame) {
  for (unsigned rate : {1000u, 3000u}) {
    BoardHost host;
    host.require_out(Request::kSetFrameRate, static_cast<std::uint16_t>(rate));
    host.require_out(Request::kSetStreaming, 1);
    host.set_speed_mm_s(100.0f);
    host.run_us(200'000.0);
    host.board().count_adc_conversions();
    const double seconds = 1.0;
    host.run_us(seconds * 1e6);
    const double per_frame = 0.4 * static_cast<double>(host.board().adc_conversions()) / (seconds * rate);
    const std::string figure = "ADC conversions per force channel per frame at " + std::to_string(rate) + " Hz";
    std::printf("%s: %.2f\n", figure.c_str(), per_frame);
    RecordProperty("adc_conversions_per_frame_at_" + std::to_string(rate), std::to_string(per_frame));
    EXPECT_NEAR(per_frame, hardware_guide_figure(figure), 0.05 * per_frame) << figure;
  }
}

// The motor's current as the firmware reads it, turning freely and under the paper's load: the
// guide's figures to 0.02 A (the mirror's reading moves by a count, 3 mA, and the loop's duty
// dithers).
TEST(BoardGuideFigures, MotorCurrentsFreeAndUnderTheTip) {
  for (const auto& [figure, normal_N] : {std::pair{std::string("motor current turning freely at 100 mm/s"), 0.0},
                                        std::pair{std::string("motor current at 100 mm/s under 2.2 N, mu 0.33"), 2.2}}) {
    BoardHost host;
    host.board().set_normal_force(normal_N);
    host.board().set_friction(0.33);
    host.set_speed_mm_s(100.0f);
    host.run_us(600'000.0);
    host.clear_records();
    host.run_us(400'000.0);
    double sum = 0.0;
    for (const TrueSpeed& s : host.true_speeds()) sum += s.sensed_A;
    const double mean = sum / static_cast<double>(host.true_speeds().size());
    std::printf("%s: %.3f A\n", figure.c_str(), mean);
    EXPECT_NEAR(mean, hardware_guide_figure(figure), 0.02) << figure;
  }
}

}  // namespace
}  // namespace nibrig::rig::usb::testing
