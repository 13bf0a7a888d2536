#include "rig/usb/usb_device_list.hpp"

#include "rig/usb/usb_control.hpp"
#include "rig/usb/usb_rig_error.hpp"

namespace nibrig::rig::usb {
namespace {

std::string name_of(const RigControllerInfo& info) {
  return info.serial.empty() ? "the rig controller at bus " + std::to_string(info.bus) +
                                   ", address " + std::to_string(info.address)
                             : "the rig controller " + info.serial;
}

bool is_rig_controller(libusb_device* device) {
  libusb_device_descriptor d{};
  return libusb_get_device_descriptor(device, &d) == 0 && d.idVendor == kVendorId &&
         d.idProduct == kProductId;
}

// Opens and identifies one device; on success the handle stays open in `opened`.
RigControllerInfo probe(libusb_device* device, libusb_device_handle** opened) {
  RigControllerInfo info;
  info.bus = libusb_get_bus_number(device);
  info.address = libusb_get_device_address(device);
  libusb_device_handle* handle = nullptr;
  const int r = libusb_open(device, &handle);
  if (r != 0) {
    info.problem = "cannot open: " + libusb_error_text(r) +
                   (r == LIBUSB_ERROR_ACCESS ? " (a udev rule for 1209:000a is missing?)" : "");
    return info;
  }
  try {
    const Identity id = ControlChannel(handle, name_of(info)).identify();
    info.serial = id.serial;
    info.protocol_version = id.protocol_version;
    info.firmware = id.firmware;
  } catch (const UsbRigError& e) {
    info.problem = e.what();
  }
  if (info.problem.empty() && opened != nullptr) {
    *opened = handle;
  } else {
    libusb_close(handle);
  }
  return info;
}

// libusb's device list, released however the caller leaves.
struct DeviceList {
  explicit DeviceList(libusb_context* context) {
    const ssize_t n = libusb_get_device_list(context, &devices);
    if (n < 0) throw UsbRigError("cannot list USB devices: " + libusb_error_text(static_cast<int>(n)));
    count = static_cast<std::size_t>(n);
  }
  ~DeviceList() { libusb_free_device_list(devices, 1); }
  DeviceList(const DeviceList&) = delete;
  DeviceList& operator=(const DeviceList&) = delete;
  libusb_device** devices = nullptr;
  std::size_t count = 0;
};

}  // namespace

std::string describe(const RigControllerInfo& info) {
  const std::string where = "bus " + std::to_string(info.bus) + ", address " + std::to_string(info.address);
  if (!info.problem.empty()) return "? (" + where + ": " + info.problem + ")";
  return info.serial + " (" + where + ", protocol " + version_text(info.protocol_version) + ", firmware " +
         info.firmware + ")";
}

std::vector<RigControllerInfo> list_rig_controllers(libusb_context* context) {
  DeviceList list(context);
  std::vector<RigControllerInfo> found;
  for (std::size_t i = 0; i < list.count; ++i) {
    if (is_rig_controller(list.devices[i])) found.push_back(probe(list.devices[i], nullptr));
  }
  return found;
}

std::vector<RigControllerInfo> list_rig_controllers() {
  libusb_context* context = nullptr;
  const int r = libusb_init(&context);
  if (r != 0) throw UsbRigError("cannot start libusb: " + libusb_error_text(r));
  try {
    auto found = list_rig_controllers(context);
    libusb_exit(context);
    return found;
  } catch (...) {
    libusb_exit(context);
    throw;
  }
}

std::optional<OpenedRig> open_rig_controller(libusb_context* context, const std::string& serial,
                                             std::vector<RigControllerInfo>& found) {
  found.clear();
  DeviceList list(context);
  std::vector<OpenedRig> matches;
  for (std::size_t i = 0; i < list.count; ++i) {
    if (!is_rig_controller(list.devices[i])) continue;
    libusb_device_handle* handle = nullptr;
    RigControllerInfo info = probe(list.devices[i], &handle);
    found.push_back(info);
    if (handle == nullptr) continue;
    if (serial.empty() || info.serial == serial) {
      OpenedRig rig{handle, {}, info};
      try {
        rig.identity = ControlChannel(handle, name_of(info)).identify();
      } catch (...) {
        libusb_close(handle);
        for (auto& m : matches) libusb_close(m.handle);
        throw;
      }
      matches.push_back(rig);
    } else {
      libusb_close(handle);
    }
  }
  if (matches.size() > 1) {
    std::string names;
    for (const auto& m : matches) names += (names.empty() ? "" : ", ") + describe(m.info);
    for (auto& m : matches) libusb_close(m.handle);
    throw UsbRigError("several nibrig rig controllers are plugged in: " + names +
                      "; name one by its serial");
  }
  if (matches.empty()) return std::nullopt;
  return matches.front();
}

std::string missing_message(const std::string& serial, const std::vector<RigControllerInfo>& found) {
  std::string message = "no nibrig rig controller (USB 1209:000a)";
  if (!serial.empty()) message += " with serial " + serial;
  if (found.empty()) return message + " on the bus";
  message += "; found: ";
  for (std::size_t i = 0; i < found.size(); ++i) message += (i ? ", " : "") + describe(found[i]);
  return message;
}

}  // namespace nibrig::rig::usb
