// One USB device as the kernel's usbfs shows it to libusb, inside a umockdev testbed: its sysfs
// entry (with the descriptors libusb reads there) and the ioctls on its /dev/bus/usb node. The
// device behind it is its owner's: control and bulk IN transfers wait here until the owner
// answers them, from any thread. Unplug and replug are the kernel's: pending transfers end with
// ESHUTDOWN and the node comes back at a new address.
#pragma once

#include <umockdev.h>

#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace nibrig::rig::usb::testing {

struct ControlTransfer {
  std::uint64_t id = 0;
  std::array<std::uint8_t, 8> setup{};
  std::vector<std::uint8_t> out;  // an OUT request's data stage
  std::size_t in_capacity = 0;    // an IN request: the most it takes
  bool in() const { return (setup[0] & 0x80) != 0; }
  std::uint16_t length() const { return static_cast<std::uint16_t>(setup[6] | (setup[7] << 8)); }
};

class UsbfsDevice {
 public:
  // `descriptors`: the device descriptor and the configuration's, as sysfs shows them.
  // `speed_mbps`: what sysfs says the link runs at (12 full speed, 480 high speed).
  UsbfsDevice(UMockdevTestbed* testbed, std::vector<std::uint8_t> descriptors, std::uint16_t vendor,
              std::uint16_t product, int address, int speed_mbps);
  ~UsbfsDevice();
  UsbfsDevice(const UsbfsDevice&) = delete;
  UsbfsDevice& operator=(const UsbfsDevice&) = delete;

  // Called (without the lock held) after each transfer libusb submits: an owner's loop wakes.
  void on_submit(std::function<void()> wake);

  void unplug();
  void replug(int new_address);
  bool plugged() const;

  // The oldest control transfer not yet taken; the owner answers it with complete_control, or
  // never (libusb times out and discards it).
  std::optional<ControlTransfer> take_control();
  // status 0 or a negative errno (-EPIPE: STALL); IN data beyond the capacity is cut.
  void complete_control(std::uint64_t id, int status, const std::vector<std::uint8_t>& in = {});

  // Bulk IN transfers on `endpoint`: whether one waits, and completing the oldest with a packet.
  bool bulk_in_waiting(std::uint8_t endpoint) const;
  void complete_bulk_in(std::uint8_t endpoint, const std::uint8_t* bytes, std::size_t length);

 private:
  struct Urb {
    UMockdevIoctlData* data = nullptr;
    std::uint64_t id = 0;
    bool taken = false;
  };
  struct Port {
    bool alive = true;
    std::deque<Urb> control, bulk_in, done, discarded;
  };

  static gboolean on_ioctl(UMockdevIoctlBase* base, UMockdevIoctlClient* client, gpointer self);
  gboolean handle_ioctl(UMockdevIoctlClient* client);
  void add_to_testbed();
  std::string devnode() const;
  std::string syspath() const;

  UMockdevTestbed* testbed_;
  std::vector<std::uint8_t> descriptors_;
  std::uint16_t vendor_, product_;
  int address_;
  int speed_mbps_;
  UMockdevIoctlBase* handler_ = nullptr;
  std::vector<std::string> attached_;
  std::function<void()> wake_;

  mutable std::mutex mutex_;  // the ioctl thread's and the owner's
  std::map<std::string, Port> ports_;
  std::string current_devnode_;
  bool plugged_ = false;
  std::uint64_t next_id_ = 1;
};

// A fresh umockdev testbed for one test (its own /sys and /dev), released at the end.
class Testbed {
 public:
  Testbed() : testbed_(umockdev_testbed_new()) {}
  ~Testbed() { g_object_unref(testbed_); }
  Testbed(const Testbed&) = delete;
  Testbed& operator=(const Testbed&) = delete;
  UMockdevTestbed* get() const { return testbed_; }

 private:
  UMockdevTestbed* testbed_;
};

}  // namespace nibrig::rig::usb::testing
