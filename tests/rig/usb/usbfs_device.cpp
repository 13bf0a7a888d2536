#include "tests/rig/usb/usbfs_device.hpp"

#include <linux/usbdevice_fs.h>
#include <sys/ioctl.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace nibrig::rig::usb::testing {
namespace {

usbdevfs_urb* urb_of(UMockdevIoctlData* data) { return reinterpret_cast<usbdevfs_urb*>(data->data); }

std::string hex_of(const std::vector<std::uint8_t>& bytes) {
  std::string hex;
  char byte[3];
  for (std::uint8_t b : bytes) {
    std::snprintf(byte, sizeof byte, "%02x", b);
    hex += byte;
  }
  return hex;
}

}  // namespace

UsbfsDevice::UsbfsDevice(UMockdevTestbed* testbed, std::vector<std::uint8_t> descriptors, std::uint16_t vendor,
                         std::uint16_t product, int address, int speed_mbps)
    : testbed_(testbed),
      descriptors_(std::move(descriptors)),
      vendor_(vendor),
      product_(product),
      address_(address),
      speed_mbps_(speed_mbps) {
  handler_ = umockdev_ioctl_base_new();
  g_signal_connect_data(handler_, "handle-ioctl", G_CALLBACK(&UsbfsDevice::on_ioctl), this, nullptr,
                        G_CONNECT_AFTER);
  add_to_testbed();
}

UsbfsDevice::~UsbfsDevice() {
  for (const auto& node : attached_) umockdev_testbed_detach_ioctl(testbed_, node.c_str(), nullptr);
  std::lock_guard lock(mutex_);
  for (auto& entry : ports_) {
    Port& port = entry.second;
    for (auto* list : {&port.control, &port.bulk_in, &port.done, &port.discarded}) {
      for (auto& urb : *list) umockdev_ioctl_data_unref(urb.data);
    }
  }
  g_object_unref(handler_);
}

void UsbfsDevice::on_submit(std::function<void()> wake) {
  std::lock_guard lock(mutex_);
  wake_ = std::move(wake);
}

std::string UsbfsDevice::devnode() const {
  char node[64];
  std::snprintf(node, sizeof node, "/dev/bus/usb/001/%03d", address_);
  return node;
}

std::string UsbfsDevice::syspath() const { return "/sys/devices/usb1/1-" + std::to_string(address_); }

void UsbfsDevice::add_to_testbed() {
  const std::string node = devnode();
  {
    std::lock_guard lock(mutex_);
    current_devnode_ = node;
    ports_[node] = Port{};
    plugged_ = true;
  }
  // The ioctl handler first, so that libusb can open the node as soon as the add uevent arrives.
  GError* error = nullptr;
  if (!umockdev_testbed_attach_ioctl(testbed_, node.c_str(), handler_, &error)) {
    const std::string message = error ? error->message : "unknown";
    g_clear_error(&error);
    throw std::runtime_error("umockdev cannot attach the device's ioctl handler: " + message);
  }
  attached_.push_back(node);
  const int a = address_;
  char description[4096];
  std::snprintf(description, sizeof description,
                "P: /devices/usb1/1-%d\n"
                "N: bus/usb/001/%03d\n"
                "E: SUBSYSTEM=usb\nE: DEVTYPE=usb_device\nE: DRIVER=usb\n"
                "E: BUSNUM=001\nE: DEVNUM=%03d\nE: DEVNAME=/dev/bus/usb/001/%03d\n"
                "E: MAJOR=189\nE: MINOR=%d\n"
                "A: busnum=1\\n\nA: devnum=%d\\n\nA: bConfigurationValue=1\\n\nA: speed=%d\\n\n"
                "A: idVendor=%04x\\n\nA: idProduct=%04x\\n\nA: dev=189:%d\\n\n"
                "H: descriptors=%s\n",
                a, a, a, a, a - 1, a, speed_mbps_, vendor_, product_, a - 1, hex_of(descriptors_).c_str());
  if (!umockdev_testbed_add_from_string(testbed_, description, &error)) {
    const std::string message = error ? error->message : "unknown";
    g_clear_error(&error);
    throw std::runtime_error("umockdev cannot add the device: " + message);
  }
}

void UsbfsDevice::unplug() {
  {
    std::lock_guard lock(mutex_);
    plugged_ = false;
    Port& port = ports_[current_devnode_];
    port.alive = false;
    // What the kernel does to the URBs of a device that left: they end with -ESHUTDOWN.
    for (auto* pending : {&port.control, &port.bulk_in}) {
      while (!pending->empty()) {
        Urb urb = pending->front();
        pending->pop_front();
        urb_of(urb.data)->status = -ESHUTDOWN;
        urb_of(urb.data)->actual_length = 0;
        port.done.push_back(urb);
      }
    }
  }
  umockdev_testbed_uevent(testbed_, syspath().c_str(), "remove");
  umockdev_testbed_remove_device(testbed_, syspath().c_str());
}

void UsbfsDevice::replug(int new_address) {
  address_ = new_address;
  add_to_testbed();
}

bool UsbfsDevice::plugged() const {
  std::lock_guard lock(mutex_);
  return plugged_;
}

std::optional<ControlTransfer> UsbfsDevice::take_control() {
  std::lock_guard lock(mutex_);
  if (!plugged_) return std::nullopt;
  Port& port = ports_[current_devnode_];
  for (Urb& urb : port.control) {
    if (urb.taken) continue;
    urb.taken = true;
    usbdevfs_urb* u = urb_of(urb.data);
    const auto* bytes = static_cast<const std::uint8_t*>(u->buffer);
    ControlTransfer t;
    t.id = urb.id;
    std::copy(bytes, bytes + 8, t.setup.begin());
    const std::size_t room = static_cast<std::size_t>(std::max(0, u->buffer_length - 8));
    if (t.in()) {
      t.in_capacity = std::min<std::size_t>(room, t.length());
    } else {
      t.out.assign(bytes + 8, bytes + 8 + std::min<std::size_t>(room, t.length()));
    }
    return t;
  }
  return std::nullopt;
}

void UsbfsDevice::complete_control(std::uint64_t id, int status, const std::vector<std::uint8_t>& in) {
  std::lock_guard lock(mutex_);
  Port& port = ports_[current_devnode_];
  auto it = std::find_if(port.control.begin(), port.control.end(), [&](const Urb& u) { return u.id == id; });
  if (it == port.control.end()) return;  // discarded meanwhile, or the device left
  usbdevfs_urb* u = urb_of(it->data);
  const std::size_t room = static_cast<std::size_t>(std::max(0, u->buffer_length - 8));
  const std::size_t n = std::min(room, in.size());
  if (n > 0) std::memcpy(static_cast<std::uint8_t*>(u->buffer) + 8, in.data(), n);
  u->status = status;
  u->actual_length = status == 0 ? static_cast<int>(n) : 0;
  port.done.push_back(*it);
  port.control.erase(it);
}

bool UsbfsDevice::bulk_in_waiting(std::uint8_t endpoint) const {
  std::lock_guard lock(mutex_);
  if (!plugged_) return false;
  const auto found = ports_.find(current_devnode_);
  if (found == ports_.end()) return false;
  return std::any_of(found->second.bulk_in.begin(), found->second.bulk_in.end(),
                     [&](const Urb& u) { return urb_of(u.data)->endpoint == endpoint; });
}

void UsbfsDevice::complete_bulk_in(std::uint8_t endpoint, const std::uint8_t* bytes, std::size_t length) {
  std::lock_guard lock(mutex_);
  if (!plugged_) return;
  Port& port = ports_[current_devnode_];
  auto it = std::find_if(port.bulk_in.begin(), port.bulk_in.end(),
                         [&](const Urb& u) { return urb_of(u.data)->endpoint == endpoint; });
  if (it == port.bulk_in.end()) return;
  usbdevfs_urb* u = urb_of(it->data);
  const std::size_t n = std::min(length, static_cast<std::size_t>(u->buffer_length));
  std::memcpy(u->buffer, bytes, n);
  u->actual_length = static_cast<int>(n);
  u->status = 0;
  port.done.push_back(*it);
  port.bulk_in.erase(it);
}

gboolean UsbfsDevice::on_ioctl(UMockdevIoctlBase*, UMockdevIoctlClient* client, gpointer self) {
  return static_cast<UsbfsDevice*>(self)->handle_ioctl(client);
}

// usbfs as the kernel offers it to libusb, for this one device.
gboolean UsbfsDevice::handle_ioctl(UMockdevIoctlClient* client) {
  const gulong request = umockdev_ioctl_client_get_request(client);
  UMockdevIoctlData* arg = umockdev_ioctl_client_get_arg(client);
  const std::string node = umockdev_ioctl_client_get_devnode(client);
  std::function<void()> wake;
  {
    std::lock_guard lock(mutex_);
    auto found = ports_.find(node);
    if (found == ports_.end()) return FALSE;
    Port& port = found->second;
    switch (request) {
      case USBDEVFS_GET_CAPABILITIES: {
        UMockdevIoctlData* caps = umockdev_ioctl_data_resolve(arg, 0, sizeof(guint32), nullptr);
        *reinterpret_cast<guint32*>(caps->data) = USBDEVFS_CAP_BULK_CONTINUATION | USBDEVFS_CAP_NO_PACKET_SIZE_LIM |
                                                  USBDEVFS_CAP_REAP_AFTER_DISCONNECT | USBDEVFS_CAP_ZERO_PACKET;
        umockdev_ioctl_data_unref(caps);
        umockdev_ioctl_client_complete(client, 0, 0);
        return TRUE;
      }
      case USBDEVFS_CLAIMINTERFACE:
      case USBDEVFS_RELEASEINTERFACE:
      case USBDEVFS_CLEAR_HALT:
      case USBDEVFS_RESETEP:
        umockdev_ioctl_client_complete(client, port.alive ? 0 : -1, port.alive ? 0 : ENODEV);
        return TRUE;
      case USBDEVFS_SUBMITURB: {
        if (!port.alive) {
          umockdev_ioctl_client_complete(client, -1, ENODEV);
          return TRUE;
        }
        UMockdevIoctlData* data = umockdev_ioctl_data_resolve(arg, 0, sizeof(usbdevfs_urb), nullptr);
        usbdevfs_urb* urb = urb_of(data);
        UMockdevIoctlData* buffer = umockdev_ioctl_data_resolve(data, offsetof(usbdevfs_urb, buffer),
                                                                static_cast<gsize>(urb->buffer_length), nullptr);
        umockdev_ioctl_data_unref(buffer);  // stays linked to `data`, which writes it back
        urb = urb_of(data);
        const Urb entry{data, next_id_++, false};
        if (urb->type == USBDEVFS_URB_TYPE_CONTROL) {
          port.control.push_back(entry);
        } else if (urb->type == USBDEVFS_URB_TYPE_BULK && (urb->endpoint & 0x80)) {
          port.bulk_in.push_back(entry);
        } else {
          urb->status = -EPIPE;  // no such endpoint: it stalls
          urb->actual_length = 0;
          port.done.push_back(entry);
        }
        umockdev_ioctl_client_complete(client, 0, 0);
        wake = wake_;
        break;
      }
      case USBDEVFS_REAPURB:
      case USBDEVFS_REAPURBNDELAY: {
        std::deque<Urb>* from = !port.discarded.empty() ? &port.discarded
                                : !port.done.empty()    ? &port.done
                                                        : nullptr;
        if (from == nullptr) {
          umockdev_ioctl_client_complete(client, -1, port.alive ? EAGAIN : ENODEV);
          return TRUE;
        }
        Urb urb = from->front();
        from->pop_front();
        UMockdevIoctlData* pointer = umockdev_ioctl_data_resolve(arg, 0, sizeof(gpointer), nullptr);
        umockdev_ioctl_data_set_ptr(pointer, 0, urb.data);
        umockdev_ioctl_data_unref(pointer);
        umockdev_ioctl_data_unref(urb.data);
        umockdev_ioctl_client_complete(client, 0, 0);
        return TRUE;
      }
      case USBDEVFS_DISCARDURB: {
        const auto address = reinterpret_cast<gulong>(*reinterpret_cast<void**>(arg->data));
        for (auto* pending : {&port.bulk_in, &port.control}) {
          auto it = std::find_if(pending->begin(), pending->end(),
                                 [&](const Urb& u) { return u.data->client_addr == address; });
          if (it == pending->end()) continue;
          urb_of(it->data)->status = -ENOENT;
          urb_of(it->data)->actual_length = 0;
          port.discarded.push_back(*it);
          pending->erase(it);
          umockdev_ioctl_client_complete(client, 0, 0);
          return TRUE;
        }
        umockdev_ioctl_client_complete(client, -1, EINVAL);  // already done: too late to discard
        return TRUE;
      }
      default:
        return FALSE;
    }
  }
  if (wake) wake();
  return TRUE;
}

}  // namespace nibrig::rig::usb::testing
