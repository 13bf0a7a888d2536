// The pen reader on an emulated Wacom Intuos S through the real libinput (udev and path backends):
// the tablet listed with its size, a drawn stroke's positions, pressure, tip and stamps, an unknown
// name refused, and an unplug mid-stroke ending the stroke.
#include "rig/pen/pen_input.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <algorithm>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

#include "tests/rig/pen/emulated_tablet.hpp"

namespace nibrig::rig::pen {
namespace {

using testing::EmulatedTablet;

// Everything the reader delivered, for a test thread to wait on.
struct PenReceived {
  std::mutex mutex;
  std::condition_variable changed;
  std::vector<PenSample> samples;
  bool removed = false;

  PenEvents events() {
    return {[this](const PenSample& s) {
              std::lock_guard lock(mutex);
              samples.push_back(s);
              changed.notify_all();
            },
            [this] {
              std::lock_guard lock(mutex);
              removed = true;
              changed.notify_all();
            }};
  }
  template <class Done>
  bool wait(Done done) {
    std::unique_lock lock(mutex);
    return changed.wait_for(lock, std::chrono::seconds(5), [&] { return done(*this); });
  }
};

class PenInputOnEmulatedTablet : public ::testing::Test {
 protected:
  void SetUp() override {
    testbed_ = umockdev_testbed_new();
    tablet_ = std::make_unique<EmulatedTablet>(testbed_, testing::wacom_intuos_s());
  }
  void TearDown() override {
    tablet_.reset();
    g_object_unref(testbed_);
  }
  // A straight stroke across the tablet at `speed_mm_s`, one report per period at the model's
  // rate, from `t0`, in real time; returns the time after it.
  double draw_line(double t0, double x0_mm, double y_mm, double speed_mm_s, double pressure, int reports) {
    const double period = 1.0 / tablet_->model().report_hz;
    for (int i = 0; i < reports; ++i) {
      const double t = t0 + i * period;
      // Each report leaves when the tablet would send it, stamped as the kernel would stamp it.
      std::this_thread::sleep_for(std::chrono::duration<double>(std::max(0.0, t - EmulatedTablet::now_s())));
      tablet_->report(t, x0_mm + speed_mm_s * (t - t0), y_mm, pressure);
    }
    return t0 + reports * period;
  }

  UMockdevTestbed* testbed_ = nullptr;
  std::unique_ptr<EmulatedTablet> tablet_;
};

TEST_F(PenInputOnEmulatedTablet, ListsTheTabletWithItsModelAndSize) {
  std::string why;
  const auto tablets = list_tablets(&why);
  ASSERT_EQ(tablets.size(), 1u) << why;
  const TabletInfo& t = tablets[0];
  EXPECT_EQ(t.name, "Wacom Intuos S Pen");
  EXPECT_EQ(t.model, "Wacom Intuos S");  // libwacom's entry for 056a:0374
  EXPECT_EQ(t.devnode, "/dev/input/event5");
  // 15200 and 9500 units at 100 units/mm; libinput's size is the maximum over the resolution.
  EXPECT_NEAR(t.width_mm, 152.0, 1e-9);
  EXPECT_NEAR(t.height_mm, 95.0, 1e-9);
  EXPECT_TRUE(t.has_pressure);
  EXPECT_FALSE(t.has_tilt);
}

TEST_F(PenInputOnEmulatedTablet, AStrokeArrivesWithItsPositionsPressureTipAndStamps) {
  PenReceived got;
  PenInput input("intuos", got.events());
  EXPECT_EQ(input.tablet().name, "Wacom Intuos S Pen");
  const double t0 = EmulatedTablet::now_s();
  tablet_->proximity_in(t0, 20.0, 40.0);
  const double t1 = draw_line(t0 + 0.01, 20.0, 40.0, 80.0, 0.5, 60);
  tablet_->report(t1, 20.0 + 80.0 * (t1 - t0 - 0.01), 40.0, 0.0);
  tablet_->proximity_out(t1 + 0.01);
  const bool left = got.wait([](PenReceived& r) { return !r.samples.empty() && !r.samples.back().in_proximity; });
  std::lock_guard lock(got.mutex);
  ASSERT_TRUE(left) << got.samples.size() << " samples, the last "
                    << (got.samples.empty() ? "none" : got.samples.back().tip_down ? "down" : "up");
  std::vector<PenSample> down;
  for (const auto& s : got.samples) {
    if (s.tip_down) down.push_back(s);
  }
  ASSERT_GE(down.size(), 55u);  // 60 reports with the tip down; libinput may fold the first into the tip event
  for (const auto& s : down) {
    // A report's position is the line's at its stamp, to the tablet's 0.01 mm quantisation.
    const double expected_x_mm = 20.0 + 80.0 * (s.time_s - t0 - 0.01);
    EXPECT_NEAR(1e3 * s.x_m, expected_x_mm, 0.006);
    EXPECT_NEAR(1e3 * s.y_m, 40.0, 0.006);
    // The kernel's stamps go through as given (to the microsecond of struct input_event).
    EXPECT_GE(s.time_s, t0 + 0.01 - 1e-6);
    EXPECT_LE(s.time_s, t1 + 1e-6);
  }
  // Half the range pressed: libinput's normalised pressure, with its small offset for the tip's
  // threshold, lands near one half.
  EXPECT_NEAR(down[down.size() / 2].pressure, 0.5, 0.05);
  // After the stroke the tip is up, then the pen leaves.
  EXPECT_FALSE(got.samples.back().tip_down);
  EXPECT_FALSE(got.samples.back().in_proximity);
}

TEST_F(PenInputOnEmulatedTablet, AnUnknownNameIsRefusedNamingTheTabletsThereAre) {
  try {
    PenInput input("cintiq", {});
    FAIL() << "an unknown tablet was opened";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("\"Wacom Intuos S Pen\""), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("cintiq"), std::string::npos) << e.what();
  }
}

TEST_F(PenInputOnEmulatedTablet, UnpluggingMidStrokeEndsTheStrokeAndIsReported) {
  PenReceived got;
  PenInput input("Wacom Intuos S", got.events());
  const double t0 = EmulatedTablet::now_s();
  tablet_->proximity_in(t0, 30.0, 30.0);
  draw_line(t0 + 0.01, 30.0, 30.0, 50.0, 0.4, 20);
  ASSERT_TRUE(got.wait([](PenReceived& r) { return !r.samples.empty() && r.samples.back().tip_down; }));
  tablet_->unplug();
  ASSERT_TRUE(got.wait([](PenReceived& r) { return r.removed; }));
  EXPECT_TRUE(input.removed());
  std::lock_guard lock(got.mutex);
  // The last sample before the removal says the tip is up and the pen gone, where it last was.
  EXPECT_FALSE(got.samples.back().tip_down);
  EXPECT_FALSE(got.samples.back().in_proximity);
  EXPECT_GT(got.samples.back().x_m, 0.030);
}

TEST_F(PenInputOnEmulatedTablet, TheNodeCanBeOpenedByPathThroughLibinputsPathBackend) {
  PenReceived got;
  PenInput input("/dev/input/event5", got.events());
  EXPECT_EQ(input.tablet().name, "Wacom Intuos S Pen");
  const double t0 = EmulatedTablet::now_s();
  tablet_->proximity_in(t0, 10.0, 10.0);
  draw_line(t0 + 0.01, 10.0, 10.0, 40.0, 0.3, 10);
  ASSERT_TRUE(got.wait([](PenReceived& r) { return r.samples.size() >= 8 && r.samples.back().tip_down; }));
}

}  // namespace
}  // namespace nibrig::rig::pen
