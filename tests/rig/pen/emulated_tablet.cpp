#include "tests/rig/pen/emulated_tablet.hpp"

#include <linux/input.h>
#include <fcntl.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace nibrig::rig::pen::testing {
namespace {

// The pen's keys (BTN_TOOL_PEN, BTN_TOUCH, the two side buttons), as the kernel lists them.
constexpr int kTabletKeys[] = {BTN_TOOL_PEN, BTN_TOUCH, BTN_STYLUS, BTN_STYLUS2};

void set_bit(std::vector<std::uint8_t>& bits, int bit) {
  bits[static_cast<std::size_t>(bit / 8)] |= static_cast<std::uint8_t>(1u << (bit % 8));
}

// sysfs's capabilities files: the bitmask as hex words of a long, most significant first.
std::string sysfs_bits(const std::vector<std::uint8_t>& bits) {
  std::vector<unsigned long> words((bits.size() + 7) / 8, 0);
  for (std::size_t i = 0; i < bits.size(); ++i) words[i / 8] |= static_cast<unsigned long>(bits[i]) << (8 * (i % 8));
  while (words.size() > 1 && words.back() == 0) words.pop_back();
  std::string text;
  for (std::size_t i = words.size(); i-- > 0;) {
    char word[24];
    std::snprintf(word, sizeof word, "%lx", words[i]);
    text += (text.empty() ? "" : " ") + std::string(word);
  }
  return text;
}

std::vector<std::uint8_t> tablet_key_bits() {
  std::vector<std::uint8_t> bits((KEY_MAX + 8) / 8, 0);
  for (int key : kTabletKeys) set_bit(bits, key);
  return bits;
}

// Position and pressure always; distance and tilt when the model has them.
std::vector<std::uint8_t> tablet_abs_bits(const EvdevTabletModel& model) {
  std::vector<std::uint8_t> bits((ABS_MAX + 8) / 8, 0);
  for (int axis : {ABS_X, ABS_Y, ABS_PRESSURE}) set_bit(bits, axis);
  if (model.distance_max > 0) set_bit(bits, ABS_DISTANCE);
  if (model.tilt_max > 0) {
    set_bit(bits, ABS_TILT_X);
    set_bit(bits, ABS_TILT_Y);
  }
  return bits;
}

std::vector<std::uint8_t> tablet_event_bits() {
  std::vector<std::uint8_t> bits((EV_MAX + 8) / 8, 0);
  for (int type : {EV_SYN, EV_KEY, EV_ABS}) set_bit(bits, type);
  return bits;
}

}  // namespace

EvdevTabletModel wacom_intuos_s() {
  EvdevTabletModel m;
  m.name = "Wacom Intuos S Pen";
  m.vendor = 0x056a;
  m.product = 0x0374;
  m.version = 0x0110;
  m.x_max = 15200;
  m.y_max = 9500;
  m.resolution = 100;
  m.pressure_max = 4095;
  m.distance_max = 63;
  m.report_hz = 133.0;
  return m;
}

// The kernel's entry for 0x357 in drivers/hid/wacom_wac.c: "Wacom Intuos Pro M", 44800 x 29600 at
// WACOM_INTUOS3_RES (200 units/mm), pressure 8191, distance 63; its pen node is that name plus
// " Pen"; as an Intuos pen it has ABS_TILT_X/Y of -64 … 63 at 57 units/radian (the same file).
// libwacom's data/intuos-pro-2-m.tablet lists usb:056a:0357 as "Wacom Intuos Pro M" (PTH-660).
// Wacom states no report rate for it; 200 Hz is what its Intuos Pro pens are measured at.
EvdevTabletModel wacom_intuos_pro_m() {
  EvdevTabletModel m;
  m.name = "Wacom Intuos Pro M Pen";
  m.vendor = 0x056a;
  m.product = 0x0357;
  m.version = 0x0110;
  m.x_max = 44800;
  m.y_max = 29600;
  m.resolution = 200;
  m.pressure_max = 8191;
  m.distance_max = 63;
  m.tilt_max = 63;
  m.tilt_resolution = 57;
  m.report_hz = 200.0;
  return m;
}

// libwacom's data/huion-h640p.tablet matches usb:256c:006d with the device name "HUION Huion
// Tablet_H640P Pen" (hid-uclogic's name: the USB strings plus " Pen"), and eleven other files list
// the same id. OpenTabletDriver's Huion/H640P.json gives the digitizer: 160 x 100 mm, 32000 x 20000
// (200 units/mm), pressure 8191. hid-uclogic's pen has no ABS_DISTANCE. Huion states 233 reports
// a second.
EvdevTabletModel huion_h640p() {
  EvdevTabletModel m;
  m.name = "HUION Huion Tablet_H640P Pen";
  m.vendor = 0x256c;
  m.product = 0x006d;
  m.version = 0x0100;
  m.x_max = 32000;
  m.y_max = 20000;
  m.resolution = 200;
  m.pressure_max = 8191;
  m.report_hz = 233.0;
  return m;
}

// libwacom's data/xp-pen-deco01-v2.tablet matches usb:28bd:0905 alone, as "UGTABLET 10 inch
// PenTablet Pad" (the USB strings the tablet gives); its pen node is "UGTABLET 10 inch PenTablet
// Pen" under hid-uclogic. OpenTabletDriver's XP-Pen/Deco 01 V2.json gives the digitizer: 254 x
// 158.75 mm, 25400 x 15875 (100 units/mm), pressure 8191. No ABS_DISTANCE; the pen's tilt is left
// out (nothing here reads tilt). XP-Pen states 266 reports a second.
EvdevTabletModel xp_pen_deco_01_v2() {
  EvdevTabletModel m;
  m.name = "UGTABLET 10 inch PenTablet Pen";
  m.vendor = 0x28bd;
  m.product = 0x0905;
  m.version = 0x0100;
  m.x_max = 25400;
  m.y_max = 15875;
  m.resolution = 100;
  m.pressure_max = 8191;
  m.report_hz = 266.0;
  return m;
}

std::vector<EvdevTabletModel> tablets_of_every_maker() {
  return {wacom_intuos_s(), wacom_intuos_pro_m(), huion_h640p(), xp_pen_deco_01_v2()};
}

EmulatedTablet::EmulatedTablet(UMockdevTestbed* testbed, EvdevTabletModel model, int event_number)
    : testbed_(testbed), model_(std::move(model)), event_number_(event_number) {
  handler_ = umockdev_ioctl_base_new();
  g_signal_connect_data(handler_, "handle-ioctl", G_CALLBACK(&EmulatedTablet::on_ioctl), this, nullptr,
                        G_CONNECT_AFTER);
  add_to_testbed();
}

EmulatedTablet::~EmulatedTablet() {
  if (plugged_) unplug();
  g_object_unref(handler_);
}

std::string EmulatedTablet::devnode() const { return "/dev/input/event" + std::to_string(event_number_); }

std::string EmulatedTablet::syspath() const {
  char path[256];
  std::snprintf(path, sizeof path, "/sys/devices/pci0000:00/0000:00:14.0/usb1/1-1/1-1:1.0/0003:%04X:%04X.0001/input/input%d",
                model_.vendor, model_.product, event_number_);
  return path;
}

double EmulatedTablet::now_s() {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

void EmulatedTablet::add_to_testbed() {
  const int minor = 64 + event_number_;
  char ids[64];
  std::snprintf(ids, sizeof ids, "%04x", model_.vendor);
  const std::string vendor = ids;
  std::snprintf(ids, sizeof ids, "%04x", model_.product);
  const std::string product = ids;
  // What udevd's input_id builtin and 60-input-id rules record for a tablet: the database entry makes
  // the device initialised for libudev (the shim serves it from the testbed).
  gchar* root_dir = umockdev_testbed_get_root_dir(testbed_);
  const std::string root = root_dir;
  g_free(root_dir);
  const std::filesystem::path data = std::filesystem::path(root) / "run/udev/data";
  std::filesystem::create_directories(data);
  {
    std::ofstream db(data / ("c13:" + std::to_string(minor)));
    db << "I:1000000\nE:ID_INPUT=1\nE:ID_INPUT_TABLET=1\nE:ID_BUS=usb\nE:ID_VENDOR_ID=" << vendor
       << "\nE:ID_MODEL_ID=" << product << "\nG:seat\n";
  }
  GError* error = nullptr;
  if (!umockdev_testbed_attach_ioctl(testbed_, devnode().c_str(), handler_, &error)) {
    const std::string message = error ? error->message : "unknown";
    g_clear_error(&error);
    throw std::runtime_error("umockdev cannot attach the tablet's ioctl handler: " + message);
  }
  const std::string input = syspath().substr(4);  // without /sys
  char description[4096];
  std::snprintf(
      description, sizeof description,
      "P: %s/event%d\nN: input/event%d\n"
      "E: DEVNAME=/dev/input/event%d\nE: MAJOR=13\nE: MINOR=%d\nE: SUBSYSTEM=input\n"
      "E: ID_INPUT=1\nE: ID_INPUT_TABLET=1\nE: ID_BUS=usb\nE: ID_VENDOR_ID=%s\nE: ID_MODEL_ID=%s\n"
      "A: dev=13:%d\\n\n\n"
      "P: %s\nE: SUBSYSTEM=input\nE: PRODUCT=3/%x/%x/%x\nE: NAME=\"%s\"\nE: PROP=1\nE: EV=b\n"
      "E: ID_INPUT=1\nE: ID_INPUT_TABLET=1\n"
      "A: name=%s\\n\nA: phys=usb-0000:00:14.0-1/input0\\n\nA: uniq=\\n\nA: properties=1\\n\n"
      "A: capabilities/ev=b\\n\nA: capabilities/key=%s\\n\nA: capabilities/abs=%s\\n\n"
      "A: id/bustype=0003\\n\nA: id/vendor=%s\\n\nA: id/product=%s\\n\nA: id/version=%04x\\n\n\n"
      "P: /devices/pci0000:00/0000:00:14.0/usb1/1-1\nE: SUBSYSTEM=usb\nE: DEVTYPE=usb_device\n"
      "A: idVendor=%s\\n\nA: idProduct=%s\\n\n",
      input.c_str(), event_number_, event_number_, event_number_, minor, vendor.c_str(), product.c_str(), minor,
      input.c_str(), model_.vendor, model_.product, model_.version, model_.name.c_str(), model_.name.c_str(),
      sysfs_bits(tablet_key_bits()).c_str(), sysfs_bits(tablet_abs_bits(model_)).c_str(), vendor.c_str(),
      product.c_str(), model_.version, vendor.c_str(), product.c_str());
  if (!umockdev_testbed_add_from_string(testbed_, description, &error)) {
    const std::string message = error ? error->message : "unknown";
    g_clear_error(&error);
    throw std::runtime_error("umockdev cannot add the tablet: " + message);
  }
  pty_ = umockdev_testbed_get_dev_fd(testbed_, devnode().c_str());
  if (pty_ < 0) throw std::runtime_error("umockdev gave the tablet's node no pty");
  // The reader's end, only to see how much it has not read yet (see write_frame).
  peer_ = ::ioctl(pty_, TIOCGPTPEER, O_RDONLY | O_NOCTTY | O_NONBLOCK);
  if (peer_ < 0) throw std::runtime_error("cannot open the tablet pty's other end");
  plugged_ = true;
}

void EmulatedTablet::unplug() {
  std::lock_guard lock(write_mutex_);
  if (!plugged_) return;
  plugged_ = false;
  const std::string event = syspath() + "/event" + std::to_string(event_number_);
  umockdev_testbed_uevent(testbed_, event.c_str(), "remove");
  umockdev_testbed_remove_device(testbed_, event.c_str());
  umockdev_testbed_detach_ioctl(testbed_, devnode().c_str(), nullptr);
  ::close(peer_);
  pty_ = peer_ = -1;
}

// evdev hands a reader whole events; a pty hands whatever it holds, and a full pty buffer (4 KiB, not
// a multiple of an event's 24 bytes) would split one. So a report waits while the reader's side
// holds half of that unread (the pty moves written bytes there a moment later, so this may let a
// report through early, never hold one back wrongly).
void EmulatedTablet::wait_for_reader() {
  for (int waited_ms = 0; waited_ms < 5000; ++waited_ms) {
    int unread = 0;
    if (::ioctl(peer_, FIONREAD, &unread) != 0 || unread < 2048) return;
    ::usleep(1000);
  }
  throw std::runtime_error("the tablet's reader took nothing for 5 s");
}

void EmulatedTablet::write_event(double t_s, std::uint16_t type, std::uint16_t code, std::int32_t value) {
  input_event ev{};
  const double whole = std::floor(t_s);
  ev.input_event_sec = static_cast<decltype(ev.input_event_sec)>(whole);
  ev.input_event_usec = static_cast<decltype(ev.input_event_usec)>(std::lround((t_s - whole) * 1e6));
  if (ev.input_event_usec >= 1000000) {
    ev.input_event_sec += 1;
    ev.input_event_usec -= 1000000;
  }
  ev.type = type;
  ev.code = code;
  ev.value = value;
  if (pty_ < 0 || ::write(pty_, &ev, sizeof ev) != static_cast<ssize_t>(sizeof ev)) {
    throw std::runtime_error("the emulated tablet could not write an event into its node");
  }
}

void EmulatedTablet::proximity_in(double t_s, double x_mm, double y_mm) {
  std::lock_guard lock(write_mutex_);
  wait_for_reader();
  write_event(t_s, EV_ABS, ABS_X, static_cast<std::int32_t>(std::lround(x_mm * model_.resolution)));
  write_event(t_s, EV_ABS, ABS_Y, static_cast<std::int32_t>(std::lround(y_mm * model_.resolution)));
  if (model_.distance_max > 0) write_event(t_s, EV_ABS, ABS_DISTANCE, model_.distance_max / 2);
  write_event(t_s, EV_KEY, BTN_TOOL_PEN, 1);
  write_event(t_s, EV_SYN, SYN_REPORT, 0);
}

void EmulatedTablet::report(double t_s, double x_mm, double y_mm, double pressure) {
  std::lock_guard lock(write_mutex_);
  wait_for_reader();
  const auto level = static_cast<std::int32_t>(std::lround(std::clamp(pressure, 0.0, 1.0) * model_.pressure_max));
  write_event(t_s, EV_ABS, ABS_X, static_cast<std::int32_t>(std::lround(x_mm * model_.resolution)));
  write_event(t_s, EV_ABS, ABS_Y, static_cast<std::int32_t>(std::lround(y_mm * model_.resolution)));
  write_event(t_s, EV_ABS, ABS_PRESSURE, level);
  if (model_.distance_max > 0) write_event(t_s, EV_ABS, ABS_DISTANCE, level > 0 ? 0 : model_.distance_max / 2);
  // hid-wacom reports the touch from the pressure crossing its threshold.
  const bool touching = level > 0;
  if (touching != touching_) write_event(t_s, EV_KEY, BTN_TOUCH, touching ? 1 : 0);
  touching_ = touching;
  write_event(t_s, EV_SYN, SYN_REPORT, 0);
}

void EmulatedTablet::proximity_out(double t_s) {
  std::lock_guard lock(write_mutex_);
  wait_for_reader();
  if (touching_) write_event(t_s, EV_KEY, BTN_TOUCH, 0);
  touching_ = false;
  write_event(t_s, EV_ABS, ABS_PRESSURE, 0);
  if (model_.distance_max > 0) write_event(t_s, EV_ABS, ABS_DISTANCE, 0);
  write_event(t_s, EV_KEY, BTN_TOOL_PEN, 0);
  write_event(t_s, EV_SYN, SYN_REPORT, 0);
}

gboolean EmulatedTablet::on_ioctl(UMockdevIoctlBase*, UMockdevIoctlClient* client, gpointer self) {
  return static_cast<EmulatedTablet*>(self)->handle_ioctl(client);
}

// evdev's ioctls as drivers/input/evdev.c answers them, for this one device.
gboolean EmulatedTablet::handle_ioctl(UMockdevIoctlClient* client) {
  const gulong request = umockdev_ioctl_client_get_request(client);
  UMockdevIoctlData* arg = umockdev_ioctl_client_get_arg(client);
  if (_IOC_TYPE(request) != 'E') return FALSE;
  const unsigned nr = _IOC_NR(request);
  const std::size_t size = _IOC_SIZE(request);
  // Copies `bytes` (at most the caller's size) into the argument; the result is the count copied.
  auto give = [&](const void* bytes, std::size_t length, bool count_result) {
    const std::size_t n = std::min(length, size);
    UMockdevIoctlData* out = umockdev_ioctl_data_resolve(arg, 0, size, nullptr);
    std::memset(out->data, 0, size);
    std::memcpy(out->data, bytes, n);
    umockdev_ioctl_data_unref(out);
    umockdev_ioctl_client_complete(client, count_result ? static_cast<glong>(n) : 0, 0);
  };
  auto give_string = [&](const std::string& text) { give(text.c_str(), text.size() + 1, true); };
  auto give_bits = [&](const std::vector<std::uint8_t>& bits) { give(bits.data(), bits.size(), true); };
  if (_IOC_DIR(request) == _IOC_READ) {
    if (request == EVIOCGVERSION) {
      const int version = EV_VERSION;
      give(&version, sizeof version, false);
      return TRUE;
    }
    if (request == EVIOCGID) {
      input_id id{BUS_USB, model_.vendor, model_.product, model_.version};
      give(&id, sizeof id, false);
      return TRUE;
    }
    switch (nr) {
      case _IOC_NR(EVIOCGNAME(0)): give_string(model_.name); return TRUE;
      case _IOC_NR(EVIOCGPHYS(0)): give_string("usb-0000:00:14.0-1/input0"); return TRUE;
      case _IOC_NR(EVIOCGUNIQ(0)): give_string(""); return TRUE;
      case _IOC_NR(EVIOCGPROP(0)): {
        std::vector<std::uint8_t> props((INPUT_PROP_MAX + 8) / 8, 0);
        set_bit(props, INPUT_PROP_POINTER);
        give_bits(props);
        return TRUE;
      }
      case _IOC_NR(EVIOCGKEY(0)):
      case _IOC_NR(EVIOCGLED(0)):
      case _IOC_NR(EVIOCGSND(0)):
      case _IOC_NR(EVIOCGSW(0)):
        give_bits(std::vector<std::uint8_t>(size, 0));  // nothing pressed, lit or switched
        return TRUE;
      default:
        break;
    }
    if (nr >= _IOC_NR(EVIOCGBIT(0, 0)) && nr <= _IOC_NR(EVIOCGBIT(EV_MAX, 0))) {
      const unsigned type = nr - _IOC_NR(EVIOCGBIT(0, 0));
      if (type == 0) give_bits(tablet_event_bits());
      else if (type == EV_KEY) give_bits(tablet_key_bits());
      else if (type == EV_ABS) give_bits(tablet_abs_bits(model_));
      else give_bits(std::vector<std::uint8_t>(size, 0));
      return TRUE;
    }
    if (nr >= _IOC_NR(EVIOCGABS(0)) && nr <= _IOC_NR(EVIOCGABS(ABS_MAX))) {
      const unsigned axis = nr - _IOC_NR(EVIOCGABS(0));
      input_absinfo info{};
      // Fuzz 0: udev's 90-libinput-fuzz-override rule moves the kernel's fuzz into a property.
      if (axis == ABS_X) info = {0, 0, model_.x_max, 0, 0, model_.resolution};
      else if (axis == ABS_Y) info = {0, 0, model_.y_max, 0, 0, model_.resolution};
      else if (axis == ABS_PRESSURE) info = {0, 0, model_.pressure_max, 0, 0, 0};
      else if (axis == ABS_DISTANCE && model_.distance_max > 0) info = {0, 0, model_.distance_max, 0, 0, 0};
      else if ((axis == ABS_TILT_X || axis == ABS_TILT_Y) && model_.tilt_max > 0)
        info = {0, -model_.tilt_max - 1, model_.tilt_max, 0, 0, model_.tilt_resolution};
      give(&info, sizeof info, false);  // evdev gives zeros for an axis the device lacks
      return TRUE;
    }
  }
  // Grabs, revokes, the clock, writes of axis info: accepted as evdev does for its owner.
  if (request == EVIOCGRAB || request == EVIOCREVOKE || request == EVIOCSCLOCKID ||
      (nr >= _IOC_NR(EVIOCSABS(0)) && nr <= _IOC_NR(EVIOCSABS(ABS_MAX)) && _IOC_DIR(request) == _IOC_WRITE)) {
    umockdev_ioctl_client_complete(client, 0, 0);
    return TRUE;
  }
  umockdev_ioctl_client_complete(client, -1, ENOTTY);
  return TRUE;
}

}  // namespace nibrig::rig::pen::testing
