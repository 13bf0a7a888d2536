// The pen reader on four makers' tablets, each emulated with its own USB id, kernel name, ranges,
// resolution, pressure levels and report rate (emulated_tablet.cpp says where each came from): the
// reader names each model right, or says it cannot, and reads each stroke's speed and force.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "rig/pen/pen_contact.hpp"
#include "rig/pen/pen_input.hpp"
#include "tests/rig/pen/emulated_tablet.hpp"
#include "tests/rig/pen/pen_speed_synthetic_stroke.hpp"

namespace nibrig::rig::pen {
namespace {

using testing::EmulatedTablet;
using testing::EvdevTabletModel;

// What the reader should say of each: libwacom 2.6's model for the id and name (the XP-Pen's entry
// is named after the USB strings the tablet gives), and whether the pen tilts.
struct MakerExpected {
  std::string model;
  bool has_tilt;
};
MakerExpected maker_expected(const EvdevTabletModel& m) {
  if (m.product == 0x0374) return {"Wacom Intuos S", false};
  if (m.product == 0x0357) return {"Wacom Intuos Pro M", true};
  if (m.vendor == 0x256c) return {"Huion H640P", false};
  return {"UGTABLET 10 inch PenTablet Pad", false};
}

// The contacts a stroke gave, for the test thread to wait on.
struct MakerContacts {
  std::mutex mutex;
  std::condition_variable changed;
  std::vector<PenContactSample> contacts;
  bool ended = false;
  double interval_s = 0.0;
};

class PenOnEveryMakersTablet : public ::testing::TestWithParam<EvdevTabletModel> {
 protected:
  void SetUp() override {
    testbed_ = umockdev_testbed_new();
    tablet_ = std::make_unique<EmulatedTablet>(testbed_, GetParam());
  }
  void TearDown() override {
    tablet_.reset();
    g_object_unref(testbed_);
  }
  UMockdevTestbed* testbed_ = nullptr;
  std::unique_ptr<EmulatedTablet> tablet_;
};

TEST_P(PenOnEveryMakersTablet, IsListedByItsOwnNameModelAndSize) {
  const EvdevTabletModel& m = GetParam();
  std::string why;
  const auto tablets = list_tablets(&why);
  ASSERT_EQ(tablets.size(), 1u) << why;
  const TabletInfo& t = tablets[0];
  EXPECT_EQ(t.name, m.name);
  EXPECT_EQ(t.model, maker_expected(m).model);
  EXPECT_TRUE(t.model_told_apart);
  // libinput's size is each axis's maximum over its resolution, exactly.
  EXPECT_NEAR(t.width_mm, static_cast<double>(m.x_max) / m.resolution, 1e-9);
  EXPECT_NEAR(t.height_mm, static_cast<double>(m.y_max) / m.resolution, 1e-9);
  EXPECT_TRUE(t.has_pressure);
  EXPECT_EQ(t.has_tilt, maker_expected(m).has_tilt);
}

// A straight line at 80 mm/s, at an angle so that both axes are rounded to the tablet's grid,
// pressed at half the pressure range, one report per period at the tablet's own rate, in real time.
TEST_P(PenOnEveryMakersTablet, AStrokesSpeedAndForceAreReadRight) {
  const EvdevTabletModel& m = GetParam();
  MakerContacts got;
  PenContactEvents events;
  events.contact = [&got](const PenContactSample& c) {
    std::lock_guard lock(got.mutex);
    got.contacts.push_back(c);
  };
  // Called under the contact's lock, after the stroke's last contact.
  events.stroke_ended = [&got](std::uint64_t, PenStrokeEnd) {
    std::lock_guard lock(got.mutex);
    got.ended = true;
    got.changed.notify_all();
  };
  PenContact contact(default_pressure_curve(), events);
  PenInput input(tablet_->devnode(), {[&contact](const PenSample& s) { contact.on_sample(s); }, {}});

  constexpr double kSpeed = 0.080, kAngle = 0.5, kPressure = 0.5, kSeconds = 0.4;
  const double period = 1.0 / m.report_hz;
  const int reports = static_cast<int>(kSeconds * m.report_hz);
  const double x0 = 30.0, y0 = 30.0;
  auto at = [&](double dt) { return std::make_pair(x0 + 1e3 * kSpeed * dt * std::cos(kAngle), y0 + 1e3 * kSpeed * dt * std::sin(kAngle)); };
  const double t0 = EmulatedTablet::now_s() + 0.01;
  std::this_thread::sleep_for(std::chrono::duration<double>(t0 - EmulatedTablet::now_s()));
  tablet_->proximity_in(t0, x0, y0);
  for (int k = 1; k <= reports + 1; ++k) {
    const double t = t0 + k * period;
    std::this_thread::sleep_for(std::chrono::duration<double>(std::max(0.0, t - EmulatedTablet::now_s())));
    const auto [x, y] = at(t - t0);
    tablet_->report(t, x, y, k <= reports ? kPressure : 0.0);  // the last lifts the tip
  }
  tablet_->proximity_out(t0 + (reports + 2) * period);
  {
    std::unique_lock lock(got.mutex);
    ASSERT_TRUE(got.changed.wait_for(lock, std::chrono::seconds(5), [&] { return got.ended; }))
        << got.contacts.size() << " contacts and no stroke end";
  }
  std::lock_guard lock(got.mutex);
  // A contact per report with the tip down (libinput may fold the first into the tip event), and
  // the end's contact.
  ASSERT_GE(got.contacts.size(), static_cast<std::size_t>(reports - 1));
  ASSERT_LE(got.contacts.size(), static_cast<std::size_t>(reports + 1));

  // The worst one estimate may be off from the tablet's grid alone (pen_speed_bounds: each
  // position rounded to 1/resolution, twice per difference); the stamps reach libinput to the
  // microsecond of struct input_event, so ±1 µs of jitter covers their rounding.
  testing::TabletModel grid;
  grid.rate_hz = m.report_hz;
  grid.jitter_s = 1e-6;
  grid.resolution_m = 1e-3 / m.resolution;
  const testing::PenSpeedBounds bounds = testing::pen_speed_bounds(kSpeed, grid);
  // libinput's pressure counts from its tip threshold, 1 % of the range (evdev-tablet.c), so half
  // the range reads up to 1.02 % of full scale light; the tablet's levels round by 1/pressure_max.
  const double force = kPressure * kDefaultFullScaleN;
  const double force_tolerance = (0.0102 + 1.0 / m.pressure_max) * kDefaultFullScaleN;
  std::size_t checked = 0;
  const double tip_up_s = t0 + (reports + 1) * period - 1e-6;
  for (std::size_t i = 2; i < got.contacts.size(); ++i) {
    const PenContactSample& c = got.contacts[i];
    if (c.time_s >= tip_up_s) continue;  // the end: speed and force 0
    EXPECT_GE(c.speed_m_s, bounds.low) << i;
    EXPECT_LE(c.speed_m_s, bounds.high) << i;
    EXPECT_NEAR(c.force_n, force, force_tolerance) << i;
    ++checked;
  }
  EXPECT_GE(checked, static_cast<std::size_t>(reports - 3));
  EXPECT_EQ(got.contacts.back().speed_m_s, 0.0);
  EXPECT_EQ(got.contacts.back().force_n, 0.0);
  // The reader measures the tablet's own rate: each interval is the period to the stamps' 1 µs
  // rounding, either end.
  EXPECT_NEAR(contact.status().report_interval_s, period, 2e-6);
  std::printf("%s at %.0f Hz: %zu contacts checked, speed bounds %.2f to %.2f mm/s\n", m.name.c_str(), m.report_hz,
              checked, 1e3 * bounds.low, 1e3 * bounds.high);
}

INSTANTIATE_TEST_SUITE_P(Makers, PenOnEveryMakersTablet, ::testing::ValuesIn(testing::tablets_of_every_maker()),
                         [](const ::testing::TestParamInfo<EvdevTabletModel>& info) {
                           std::string name;
                           for (char c : info.param.name) {
                             if (std::isalnum(static_cast<unsigned char>(c))) name += c;
                           }
                           return name;
                         });

// A Huion whose kernel name libwacom lists for none of the models sharing its id (hid-generic
// names a tablet without USB strings "HID 256c:006d Pen"): the reader claims no model. libwacom's
// lookup by id alone would call it a Huion H950P.
TEST(PenOnAnUnnamedHuion, ClaimsNoModelAndSaysWhyButKeepsTheKernelsSize) {
  UMockdevTestbed* testbed = umockdev_testbed_new();
  {
    EvdevTabletModel m = testing::huion_h640p();
    m.name = "HID 256c:006d Pen";
    EmulatedTablet tablet(testbed, m);
    std::string why;
    const auto tablets = list_tablets(&why);
    ASSERT_EQ(tablets.size(), 1u) << why;
    EXPECT_EQ(tablets[0].name, "HID 256c:006d Pen");
    EXPECT_EQ(tablets[0].model, "a GAOMON or Huion tablet (model not told apart by its USB id 256c:006d)");
    EXPECT_FALSE(tablets[0].model_told_apart);
    EXPECT_NEAR(tablets[0].width_mm, 160.0, 1e-9);
    EXPECT_NEAR(tablets[0].height_mm, 100.0, 1e-9);
    // Nor is it opened as the model it is not.
    EXPECT_THROW(PenInput("H950P", {}), std::invalid_argument);
    EXPECT_NO_THROW(PenInput("huion", {}));
  }
  g_object_unref(testbed);
}

}  // namespace
}  // namespace nibrig::rig::pen
