// A pen tablet as the kernel shows it to libinput, inside a umockdev testbed: its sysfs entries and
// udev properties, the evdev ioctls on its /dev/input node (answered from the model's axes), and the
// input events the kernel's hid-wacom would send, written into the node's pty with the stamps the
// test gives. Run under tests/rig/pen/run_under_umockdev.sh (umockdev's preload and the shim that
// gives it udev's database and fstat).
#pragma once

#include <umockdev.h>

#include <cstdint>
#include <mutex>
#include <ostream>
#include <string>
#include <vector>

namespace nibrig::rig::pen::testing {

// A tablet model by the kernel's numbers (drivers/hid/wacom_wac.c, hid-uclogic) and libwacom's entry.
struct EvdevTabletModel {
  std::string name;  // the kernel's device name
  std::uint16_t vendor = 0, product = 0, version = 0;
  int x_max = 0, y_max = 0;  // ABS_X, ABS_Y maxima
  int resolution = 0;        // units per mm
  int pressure_max = 0, distance_max = 0;  // distance_max 0: the tablet has no ABS_DISTANCE
  int tilt_max = 0;          // ABS_TILT_X/Y span -tilt_max-1 … tilt_max; 0: no tilt
  int tilt_resolution = 0;   // tilt units per radian
  double report_hz = 0.0;  // how often the pen reports while in reach
};

// Wacom Intuos S (CTL-4100, USB 056a:0374): 152 x 95 mm active area at 100 units/mm, 4096
// pressure levels, no tilt, 133 reports a second.
EvdevTabletModel wacom_intuos_s();
// Wacom Intuos Pro M (PTH-660, USB 056a:0357): 224 x 148 mm at 200 units/mm, 8192 levels, tilt,
// 200 reports a second.
EvdevTabletModel wacom_intuos_pro_m();
// Huion H640P (USB 256c:006d, an id Huion shares among many models): 160 x 100 mm at 200 units/mm,
// 8192 levels, 233 reports a second.
EvdevTabletModel huion_h640p();
// XP-Pen Deco 01 V2 (USB 28bd:0905): 254 x 158.75 mm at 100 units/mm, 8192 levels, 266 reports a
// second.
EvdevTabletModel xp_pen_deco_01_v2();
// The four, for tests that run on every maker's tablets.
std::vector<EvdevTabletModel> tablets_of_every_maker();
// A test parameter as gtest lists it: the name, not the struct's bytes (which hold pointers, and
// would change ctest's test names from one discovery to the next).
inline void PrintTo(const EvdevTabletModel& model, std::ostream* os) { *os << model.name; }

class EmulatedTablet {
 public:
  EmulatedTablet(UMockdevTestbed* testbed, EvdevTabletModel model, int event_number = 5);
  ~EmulatedTablet();
  EmulatedTablet(const EmulatedTablet&) = delete;
  EmulatedTablet& operator=(const EmulatedTablet&) = delete;

  const EvdevTabletModel& model() const { return model_; }
  std::string devnode() const;

  // One report each, stamped t_s on CLOCK_MONOTONIC, positions in mm from the top-left corner and
  // pressure as a fraction of the range (0 … 1), quantised as the tablet does.
  void proximity_in(double t_s, double x_mm, double y_mm);
  void report(double t_s, double x_mm, double y_mm, double pressure);
  void proximity_out(double t_s);
  // The tablet leaves: udev's remove uevent, and the node goes away.
  void unplug();

  static double now_s();

 private:
  static gboolean on_ioctl(UMockdevIoctlBase* base, UMockdevIoctlClient* client, gpointer self);
  gboolean handle_ioctl(UMockdevIoctlClient* client);
  void wait_for_reader();
  void write_event(double t_s, std::uint16_t type, std::uint16_t code, std::int32_t value);
  void add_to_testbed();
  std::string syspath() const;

  UMockdevTestbed* testbed_;
  EvdevTabletModel model_;
  int event_number_;
  UMockdevIoctlBase* handler_ = nullptr;
  int pty_ = -1, peer_ = -1;
  bool touching_ = false;
  bool plugged_ = false;
  std::mutex write_mutex_;
};

}  // namespace nibrig::rig::pen::testing
