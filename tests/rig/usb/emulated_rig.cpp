#include "tests/rig/usb/emulated_rig.hpp"

#include <linux/usbdevice_fs.h>
#include <sys/ioctl.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace nibrig::rig::usb::testing {
namespace {

constexpr double kMotorTau_s = 0.05;  // the speed loop's first-order response
constexpr std::uint64_t kPacketAgeUs = 8000;  // PROTOCOL.md: a packet at least every 10 ms

// Device, configuration, interface and one bulk IN endpoint descriptor (PROTOCOL.md "Device").
std::string descriptor_hex() {
  const std::vector<std::uint8_t> d = {
      18, 1, 0x00, 0x02, 0xFF, 0, 0, 64,              // USB 2.0, vendor class, EP0 64 bytes
      kVendorId & 0xFF, kVendorId >> 8, kProductId & 0xFF, kProductId >> 8,
      0x00, 0x01, 0, 0, 0, 1,                         // bcdDevice 1.00, no strings, 1 config
      9, 2, 25, 0, 1, 1, 0, 0x80, 50,                 // config 1: 25 bytes, 1 interface
      9, 4, 0, 0, 1, 0xFF, 0, 0, 0,                   // interface 0: 1 endpoint, vendor class
      7, 5, kStreamEndpoint, 2, 0x00, 0x02, 0};       // bulk IN 0x81, 512 bytes
  std::string hex;
  char byte[3];
  for (std::uint8_t b : d) {
    std::snprintf(byte, sizeof byte, "%02x", b);
    hex += byte;
  }
  return hex;
}

usbdevfs_urb* urb_of(UMockdevIoctlData* data) { return reinterpret_cast<usbdevfs_urb*>(data->data); }

}  // namespace

EmulatedRig::EmulatedRig(UMockdevTestbed* testbed, EmulatedRigConfig config)
    : testbed_(testbed),
      config_(std::move(config)),
      power_up_(std::chrono::steady_clock::now() - std::chrono::seconds(5)),  // on for a while
      frame_rate_hz_(config_.frame_rate_hz) {
  handler_ = umockdev_ioctl_base_new();
  g_signal_connect_data(handler_, "handle-ioctl", G_CALLBACK(&EmulatedRig::on_ioctl), this, nullptr,
                        G_CONNECT_AFTER);
  next_sample_us_ = clock_us();
  last_control_us_ = clock_us();
  add_to_testbed();
  firmware_ = std::thread([this] { firmware_loop(); });
}

EmulatedRig::~EmulatedRig() {
  running_ = false;
  firmware_.join();
  for (const auto& node : attached_) umockdev_testbed_detach_ioctl(testbed_, node.c_str(), nullptr);
  std::lock_guard lock(mutex_);
  for (auto& [node, port] : ports_) {
    for (auto* list : {&port.pending_in, &port.pending_control, &port.done, &port.discarded}) {
      for (auto& urb : *list) umockdev_ioctl_data_unref(urb.data);
    }
  }
  g_object_unref(handler_);
}

std::string EmulatedRig::devnode() const {
  char node[64];
  std::snprintf(node, sizeof node, "/dev/bus/usb/001/%03d", config_.address);
  return node;
}

std::string EmulatedRig::syspath() const { return "/sys/devices/usb1/1-" + std::to_string(config_.address); }

void EmulatedRig::add_to_testbed() {
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
    throw std::runtime_error("umockdev cannot attach the rig's ioctl handler: " + message);
  }
  attached_.push_back(node);
  const int a = config_.address;
  char description[2048];
  std::snprintf(description, sizeof description,
                "P: /devices/usb1/1-%d\n"
                "N: bus/usb/001/%03d\n"
                "E: SUBSYSTEM=usb\nE: DEVTYPE=usb_device\nE: DRIVER=usb\n"
                "E: BUSNUM=001\nE: DEVNUM=%03d\nE: DEVNAME=/dev/bus/usb/001/%03d\n"
                "E: MAJOR=189\nE: MINOR=%d\n"
                "A: busnum=1\\n\nA: devnum=%d\\n\nA: bConfigurationValue=1\\n\nA: speed=480\\n\n"
                "A: idVendor=%04x\\n\nA: idProduct=%04x\\n\nA: dev=189:%d\\n\n"
                "H: descriptors=%s\n",
                a, a, a, a, a - 1, a, kVendorId, kProductId, a - 1, descriptor_hex().c_str());
  if (!umockdev_testbed_add_from_string(testbed_, description, &error)) {
    const std::string message = error ? error->message : "unknown";
    g_clear_error(&error);
    throw std::runtime_error("umockdev cannot add the rig: " + message);
  }
}

void EmulatedRig::unplug() {
  {
    std::lock_guard lock(mutex_);
    plugged_ = false;
    streaming_ = false;  // a device without power streams nothing
    Port& port = ports_[current_devnode_];
    port.alive = false;
    // What the kernel does to URBs of a device that left: they end with -ESHUTDOWN.
    for (auto* pending : {&port.pending_in, &port.pending_control}) {
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

void EmulatedRig::replug(int new_address) {
  config_.address = new_address;
  {
    std::lock_guard lock(mutex_);
    mode_ = Mode::kIdle;  // it lost power: the motor is at rest
    target_m_s_ = 0.0;
  }
  add_to_testbed();
}

void EmulatedRig::drop_frames(unsigned count) {
  std::lock_guard lock(mutex_);
  drop_ += count;
}
void EmulatedRig::reorder_next_packet() {
  std::lock_guard lock(mutex_);
  reorder_ = true;
}
void EmulatedRig::duplicate_next_packet() {
  std::lock_guard lock(mutex_);
  duplicate_ = true;
}
bool EmulatedRig::streaming() const {
  std::lock_guard lock(mutex_);
  return streaming_;
}
unsigned EmulatedRig::frames_duplicated() const {
  std::lock_guard lock(mutex_);
  return duplicated_;
}
void EmulatedRig::tap(std::uint64_t device_us, double extra_N) {
  std::lock_guard lock(mutex_);
  tap_ = std::make_pair(device_us, extra_N);
}

std::uint64_t EmulatedRig::tapped_at_us() const {
  std::lock_guard lock(mutex_);
  return tapped_at_us_;
}

void EmulatedRig::hold_stream(bool hold) {
  std::lock_guard lock(mutex_);
  hold_ = hold;
}
void EmulatedRig::refuse_next(Request request, Refusal why) {
  std::lock_guard lock(mutex_);
  refuse_next_ = std::make_pair(static_cast<std::uint8_t>(request), why);
}
void EmulatedRig::ignore_next_control() {
  std::lock_guard lock(mutex_);
  ignore_next_ = true;
}

DeviceStatus EmulatedRig::status() const {
  std::lock_guard lock(mutex_);
  return {flags_, mode_, fault_, sequence_, target_m_s_,
          static_cast<std::uint16_t>(profile_ ? profile_->points().size() : 0), refused_request_, refusal_};
}
std::vector<ProfilePoint> EmulatedRig::held_profile() const {
  std::lock_guard lock(mutex_);
  return profile_ ? profile_->points() : std::vector<ProfilePoint>{};
}
ForceCalibration EmulatedRig::calibration() const {
  std::lock_guard lock(mutex_);
  return calibration_;
}
std::uint32_t EmulatedRig::frames_sampled() const {
  std::lock_guard lock(mutex_);
  return sequence_;
}
std::uint32_t EmulatedRig::first_streamed_sequence() const {
  std::lock_guard lock(mutex_);
  return first_streamed_;
}
std::uint32_t EmulatedRig::last_sent_sequence() const {
  std::lock_guard lock(mutex_);
  return last_sent_;
}
unsigned EmulatedRig::control_requests() const {
  std::lock_guard lock(mutex_);
  return control_requests_;
}

std::uint64_t EmulatedRig::clock_us() const { return device_us_at(std::chrono::steady_clock::now()); }

std::uint64_t EmulatedRig::device_us_at(std::chrono::steady_clock::time_point host) const {
  const double elapsed_us = std::chrono::duration<double, std::micro>(host - power_up_).count();
  return static_cast<std::uint64_t>(elapsed_us * (1.0 + config_.clock_ppm * 1e-6));
}

gboolean EmulatedRig::on_ioctl(UMockdevIoctlBase*, UMockdevIoctlClient* client, gpointer self) {
  return static_cast<EmulatedRig*>(self)->handle_ioctl(client);
}

// usbfs as the kernel offers it to libusb, for this one device.
gboolean EmulatedRig::handle_ioctl(UMockdevIoctlClient* client) {
  const gulong request = umockdev_ioctl_client_get_request(client);
  UMockdevIoctlData* arg = umockdev_ioctl_client_get_arg(client);
  const std::string node = umockdev_ioctl_client_get_devnode(client);
  std::lock_guard lock(mutex_);
  auto found = ports_.find(node);
  if (found == ports_.end()) return FALSE;
  Port& port = found->second;
  switch (request) {
    case USBDEVFS_GET_CAPABILITIES: {
      UMockdevIoctlData* caps = umockdev_ioctl_data_resolve(arg, 0, sizeof(guint32), nullptr);
      *reinterpret_cast<guint32*>(caps->data) = USBDEVFS_CAP_BULK_CONTINUATION |
                                                USBDEVFS_CAP_NO_PACKET_SIZE_LIM |
                                                USBDEVFS_CAP_REAP_AFTER_DISCONNECT |
                                                USBDEVFS_CAP_ZERO_PACKET;
      umockdev_ioctl_data_unref(caps);
      umockdev_ioctl_client_complete(client, 0, 0);
      return TRUE;
    }
    case USBDEVFS_CLAIMINTERFACE:
    case USBDEVFS_RELEASEINTERFACE:
    case USBDEVFS_CLEAR_HALT:
    case USBDEVFS_RESETEP:
      if (!port.alive) {
        umockdev_ioctl_client_complete(client, -1, ENODEV);
      } else {
        umockdev_ioctl_client_complete(client, 0, 0);
      }
      return TRUE;
    case USBDEVFS_SUBMITURB: {
      if (!port.alive) {
        umockdev_ioctl_client_complete(client, -1, ENODEV);
        return TRUE;
      }
      UMockdevIoctlData* data = umockdev_ioctl_data_resolve(arg, 0, sizeof(usbdevfs_urb), nullptr);
      usbdevfs_urb* urb = urb_of(data);
      UMockdevIoctlData* buffer = umockdev_ioctl_data_resolve(
          data, offsetof(usbdevfs_urb, buffer), static_cast<gsize>(urb->buffer_length), nullptr);
      umockdev_ioctl_data_unref(buffer);  // stays linked to `data`, which writes it back
      urb = urb_of(data);
      auto* bytes = static_cast<std::uint8_t*>(urb->buffer);
      if (urb->type == USBDEVFS_URB_TYPE_CONTROL) {
        ++control_requests_;
        last_control_us_ = clock_us();
        const Reply reply = control(bytes, bytes + 8);
        if (reply.ignore) {
          port.pending_control.push_back({data});  // never answered: libusb times out, discards it
        } else {
          urb->status = reply.stall ? -EPIPE : 0;
          std::copy(reply.data.begin(), reply.data.end(), bytes + 8);
          urb->actual_length = static_cast<int>(reply.data.size());
          port.done.push_back({data});
        }
      } else if (urb->type == USBDEVFS_URB_TYPE_BULK && urb->endpoint == kStreamEndpoint) {
        port.pending_in.push_back({data});
      } else {
        urb->status = -EPIPE;  // no such endpoint: it stalls
        urb->actual_length = 0;
        port.done.push_back({data});
      }
      umockdev_ioctl_client_complete(client, 0, 0);
      return TRUE;
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
      for (auto* pending : {&port.pending_in, &port.pending_control}) {
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

void EmulatedRig::firmware_loop() {
  while (running_) {
    std::this_thread::sleep_for(std::chrono::microseconds(500));
    std::lock_guard lock(mutex_);
    const std::uint64_t now = clock_us();
    // Watchdog (PROTOCOL.md): the motor stops when the host has been silent too long.
    if ((mode_ == Mode::kSpeed || mode_ == Mode::kProfile) && now - last_control_us_ > 500'000) {
      mode_ = Mode::kIdle;
      target_m_s_ = 0.0;
      fault_ = Fault::kWatchdog;
      flags_ |= kWatchdogStopped;
    }
    if (mode_ == Mode::kProfile && profile_) {
      const double t = static_cast<double>(now - profile_start_us_) * 1e-6;
      target_m_s_ = profile_->speed_at(t);
      if (t > profile_->duration_s()) mode_ = Mode::kProfileDone;
    }
    if (mode_ == Mode::kSpeed || mode_ == Mode::kProfile) {
      flags_ |= kProfileRunning;
    } else {
      flags_ &= static_cast<std::uint16_t>(~kProfileRunning);
    }
    sample_until(now);
    if (plugged_) send_packets(now);
  }
}

void EmulatedRig::sample_until(std::uint64_t now_us) {
  const std::uint64_t period_us = 1'000'000 / frame_rate_hz_;
  while (next_sample_us_ <= now_us) {
    const double dt = static_cast<double>(period_us) * 1e-6;
    speed_m_s_ += (target_m_s_ - speed_m_s_) * (1.0 - std::exp(-dt / kMotorTau_s));
    SensorFrame f;
    f.device_time_us = next_sample_us_;
    f.sequence = sequence_++;
    f.speed_m_s = static_cast<float>(speed_m_s_);
    f.normal_force_N = static_cast<float>(kLoadN - force_zero_N_);
    f.tangential_force_N = static_cast<float>(0.3 * (kLoadN - force_zero_N_));
    f.flags = flags_;
    if (tap_ && next_sample_us_ >= tap_->first) {
      f.normal_force_N += static_cast<float>(tap_->second);
      tapped_at_us_ = next_sample_us_;
      tap_.reset();
    }
    next_sample_us_ += period_us;
    if (!streaming_ || !plugged_) continue;
    if (drop_ > 0) {  // sampled, never sent: a gap in the sequence
      --drop_;
      continue;
    }
    if (!any_streamed_) {
      any_streamed_ = true;
      first_streamed_ = f.sequence;
    }
    fifo_.push_back(f);
    if (fifo_.size() > 8192) fifo_.pop_front();  // the device's buffer: the oldest is lost
  }
}

void EmulatedRig::send_packets(std::uint64_t now_us) {
  Port& port = ports_[current_devnode_];
  while (!hold_ && !port.pending_in.empty() && !fifo_.empty() &&
         (fifo_.size() >= config_.frames_per_packet || now_us - fifo_.front().device_time_us >= kPacketAgeUs)) {
    const std::size_t n = std::min<std::size_t>({fifo_.size(), config_.frames_per_packet, kMaxFramesPerPacket});
    std::vector<SensorFrame> frames(fifo_.begin(), fifo_.begin() + static_cast<std::ptrdiff_t>(n));
    fifo_.erase(fifo_.begin(), fifo_.begin() + static_cast<std::ptrdiff_t>(n));
    if (duplicate_) {  // the same frames again at the head of the queue: the next packet repeats them
      fifo_.insert(fifo_.begin(), frames.begin(), frames.end());
      duplicated_ += static_cast<unsigned>(frames.size());
      duplicate_ = false;
    }
    if (reorder_ && frames.size() >= 2) {
      std::swap(frames[0], frames[1]);
      reorder_ = false;
    }
    for (const auto& f : frames) last_sent_ = std::max(last_sent_, f.sequence);
    const auto packet = encode_frame_packet(frames);
    Urb urb = port.pending_in.front();
    port.pending_in.pop_front();
    usbdevfs_urb* u = urb_of(urb.data);
    const std::size_t bytes = std::min(packet.size(), static_cast<std::size_t>(u->buffer_length));
    std::memcpy(u->buffer, packet.data(), bytes);
    u->actual_length = static_cast<int>(bytes);
    u->status = 0;
    port.done.push_back(urb);
  }
}

}  // namespace nibrig::rig::usb::testing
