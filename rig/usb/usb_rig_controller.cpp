#include "rig/usb/usb_rig_controller.hpp"

#include <algorithm>
#include <array>
#include <cstdio>

#include "rig/usb/usb_control.hpp"
#include "rig/usb/usb_rig_error.hpp"

namespace nibrig::rig::usb {

struct UsbRigController::Transfer {
  UsbRigController* owner = nullptr;
  libusb_transfer* transfer = nullptr;
  std::array<std::uint8_t, kMaxPacketBytes> buffer{};
  std::atomic<bool> busy{false};  // submitted and not yet back
};

UsbRigController::UsbRigController(Options options)
    : options_(std::move(options)), queue_(options_.queue_frames) {
  const int r = libusb_init(&context_);
  if (r != 0) throw UsbRigError("cannot start libusb: " + libusb_error_text(r));
  try {
    std::vector<RigControllerInfo> found;
    auto opened = open_rig_controller(context_, options_.serial, found);
    if (!opened) throw UsbRigError(missing_message(options_.serial, found));
    handle_ = opened->handle;
    identity_ = opened->identity;
    serial_ = identity_.serial;
    for (unsigned i = 0; i < std::max(1u, options_.transfers_in_flight); ++i) {
      auto t = std::make_unique<Transfer>();
      t->owner = this;
      t->transfer = libusb_alloc_transfer(0);
      if (t->transfer == nullptr) throw UsbRigError("cannot allocate a libusb transfer");
      transfers_.push_back(std::move(t));
    }
    keep_alive_ = libusb_alloc_transfer(0);
    if (keep_alive_ == nullptr) throw UsbRigError("cannot allocate a libusb transfer");
    keep_alive_buffer_.resize(LIBUSB_CONTROL_SETUP_SIZE + kStatusBytes12);
    // Hotplug tells at once when the device leaves or comes back; without it (some platforms) a
    // transfer's NO_DEVICE and the periodic rescan do the same, only later. No ENUMERATE flag: the
    // device at hand was just opened, and an arrival reported twice costs only a rescan anyway.
    if (libusb_has_capability(LIBUSB_CAP_HAS_HOTPLUG) != 0) {
      has_hotplug_ = libusb_hotplug_register_callback(
                         context_,
                         static_cast<libusb_hotplug_event>(LIBUSB_HOTPLUG_EVENT_DEVICE_ARRIVED |
                                                           LIBUSB_HOTPLUG_EVENT_DEVICE_LEFT),
                         static_cast<libusb_hotplug_flag>(0), kVendorId, kProductId,
                         LIBUSB_HOTPLUG_MATCH_ANY, &UsbRigController::on_hotplug, this,
                         &hotplug_) == LIBUSB_SUCCESS;
    }
    start_streaming();
    connected_ = true;
  } catch (...) {
    for (auto& t : transfers_) {
      if (t->busy) libusb_cancel_transfer(t->transfer);
    }
    timeval tv{0, 100000};
    while (in_flight_ > 0) libusb_handle_events_timeout_completed(context_, &tv, nullptr);
    if (handle_ != nullptr) {
      libusb_release_interface(handle_, kInterface);
      libusb_close(handle_);
    }
    for (auto& t : transfers_) libusb_free_transfer(t->transfer);
    libusb_free_transfer(keep_alive_);
    if (has_hotplug_) libusb_hotplug_deregister_callback(context_, hotplug_);
    libusb_exit(context_);
    throw;
  }
  events_ = std::thread([this] { event_loop(); });
}

UsbRigController::~UsbRigController() {
  stopping_ = true;
  events_.join();
  for (auto& t : transfers_) libusb_free_transfer(t->transfer);
  libusb_free_transfer(keep_alive_);
  if (has_hotplug_) libusb_hotplug_deregister_callback(context_, hotplug_);
  libusb_exit(context_);
}

void UsbRigController::start_streaming() {
  const int r = libusb_claim_interface(handle_, kInterface);
  if (r != 0) {
    throw UsbRigError("cannot claim the rig controller " + serial_ + "'s interface: " +
                      libusb_error_text(r) + " (is another program using it?)");
  }
  ControlChannel(handle_, "the rig controller " + serial_, options_.control_timeout_ms)
      .out(Request::kSetStreaming, 1, 0);
  // Nothing is in flight here, so the callbacks' tracker can be reset from this thread.
  tracker_.restart();
  for (auto& t : transfers_) {
    libusb_fill_bulk_transfer(t->transfer, handle_, kStreamEndpoint, t->buffer.data(),
                              static_cast<int>(t->buffer.size()), &UsbRigController::on_bulk, t.get(),
                              static_cast<unsigned>(options_.transfer_timeout.count()));
    t->busy = true;
    ++in_flight_;
    const int s = libusb_submit_transfer(t->transfer);
    if (s != 0) {
      t->busy = false;
      --in_flight_;
      throw UsbRigError("cannot start the rig controller " + serial_ + "'s stream: " +
                        libusb_error_text(s));
    }
  }
}

void UsbRigController::close_device() {
  std::lock_guard lock(device_mutex_);
  if (handle_ == nullptr) return;
  libusb_release_interface(handle_, kInterface);
  libusb_close(handle_);
  handle_ = nullptr;
}

void UsbRigController::set_fault(std::string fault) {
  std::lock_guard lock(fault_mutex_);
  last_fault_ = std::move(fault);
}

void UsbRigController::event_loop() {
  using clock = std::chrono::steady_clock;
  auto next_keep_alive = clock::now();
  auto next_rescan = clock::now();
  bool cancelling = false;
  const auto keep_alive_period =
      options_.keep_alive_period.count() > 0
          ? options_.keep_alive_period
          : std::chrono::milliseconds(std::max(10u, identity_.watchdog_timeout_ms / 3));
  while (!stopping_) {
    timeval tv{0, 20000};  // short, so that an unplug, a stop or a keep-alive is seen promptly
    libusb_handle_events_timeout_completed(context_, &tv, nullptr);
    const auto now = clock::now();
    if (lost_) {
      if (connected_.exchange(false)) {
        ++disconnects_;
        set_fault("the rig controller " + serial_ + " was unplugged; " +
                  std::to_string(received_.load()) + " frames received so far are kept");
      }
      if (!cancelling) {
        for (auto& t : transfers_) {
          if (t->busy) libusb_cancel_transfer(t->transfer);
        }
        if (keep_alive_in_flight_) libusb_cancel_transfer(keep_alive_);
        cancelling = true;
      }
      if (in_flight_ == 0 && !keep_alive_in_flight_) {
        close_device();
        lost_ = false;
        cancelling = false;
        next_rescan = now;
      }
    } else if (connected_) {
      // A transfer that ended in an error other than an unplug is not resubmitted by its callback;
      // try it again here, outside the callback.
      for (auto& t : transfers_) {
        if (!t->busy && handle_ != nullptr) {
          t->busy = true;
          ++in_flight_;
          if (libusb_submit_transfer(t->transfer) != 0) {
            t->busy = false;
            --in_flight_;
          }
        }
      }
      if (options_.keep_alive && now >= next_keep_alive && !keep_alive_in_flight_) {
        submit_keep_alive();
        next_keep_alive = now + keep_alive_period;
      }
    } else if (arrival_seen_.exchange(false) || now >= next_rescan) {
      try_reconnect();
      next_rescan = now + options_.rescan_period;
    }
  }
  // Shutting down: every transfer back, the motor and the stream stopped (a host that goes away
  // should not leave the turntable running until the watchdog notices), then the device closed.
  for (auto& t : transfers_) {
    if (t->busy) libusb_cancel_transfer(t->transfer);
  }
  if (keep_alive_in_flight_) libusb_cancel_transfer(keep_alive_);
  for (int i = 0; i < 200 && (in_flight_ > 0 || keep_alive_in_flight_); ++i) {
    timeval tv{0, 10000};
    libusb_handle_events_timeout_completed(context_, &tv, nullptr);
  }
  if (connected_) {
    std::lock_guard lock(device_mutex_);
    if (handle_ != nullptr) {
      try {
        ControlChannel channel(handle_, "the rig controller " + serial_, 200);
        channel.out(Request::kStop, 0, 0);
        channel.out(Request::kSetStreaming, 0, 0);
      } catch (const UsbRigError&) {
        // Unplugged or not answering while closing: nothing left to stop.
      }
    }
  }
  close_device();
}

void UsbRigController::try_reconnect() {
  std::vector<RigControllerInfo> found;
  std::optional<OpenedRig> opened;
  try {
    opened = open_rig_controller(context_, serial_, found);
  } catch (const UsbRigError& e) {
    set_fault(e.what());
    return;
  }
  if (!opened) return;
  {
    std::lock_guard lock(device_mutex_);
    handle_ = opened->handle;
    identity_ = opened->identity;
  }
  try {
    start_streaming();
  } catch (const UsbRigError& e) {
    set_fault(e.what());
    for (auto& t : transfers_) {
      if (t->busy) libusb_cancel_transfer(t->transfer);
    }
    while (in_flight_ > 0) {
      timeval tv{0, 10000};
      libusb_handle_events_timeout_completed(context_, &tv, nullptr);
    }
    close_device();
    return;
  }
  // The unplug stays the last fault: a capture reports it even though streaming resumed.
  ++reconnects_;
  connected_ = true;
}

void UsbRigController::submit_keep_alive() {
  libusb_fill_control_setup(keep_alive_buffer_.data(), kRequestTypeIn,
                            static_cast<std::uint8_t>(Request::kGetStatus), 0, 0, kStatusBytes12);
  libusb_fill_control_transfer(keep_alive_, handle_, keep_alive_buffer_.data(),
                               &UsbRigController::on_keep_alive, this, 500);
  keep_alive_in_flight_ = true;
  const int r = libusb_submit_transfer(keep_alive_);
  if (r != 0) {
    keep_alive_in_flight_ = false;
    if (r == LIBUSB_ERROR_NO_DEVICE) lost_ = true;
  }
}

void LIBUSB_CALL UsbRigController::on_keep_alive(libusb_transfer* transfer) {
  auto* self = static_cast<UsbRigController*>(transfer->user_data);
  if (transfer->status == LIBUSB_TRANSFER_COMPLETED &&
      transfer->actual_length >= static_cast<int>(kStatusBytes)) {
    const DeviceStatus s = decode_status(std::span<const std::uint8_t>(
        libusb_control_transfer_get_data(transfer), static_cast<std::size_t>(transfer->actual_length)));
    self->device_flags_ = s.flags;
    if (s.fault != Fault::kNone) {
      std::string why = "the rig controller " + self->serial_ + " stopped the motor: " +
                        fault_cause_text(static_cast<std::uint8_t>(s.fault), static_cast<std::uint8_t>(s.cause));
      self->set_fault(why);
      std::lock_guard lock(self->fault_mutex_);
      self->device_fault_ = std::move(why);
    }
  } else if (transfer->status == LIBUSB_TRANSFER_NO_DEVICE) {
    self->lost_ = true;
  }
  self->keep_alive_in_flight_ = false;
}

void LIBUSB_CALL UsbRigController::on_bulk(libusb_transfer* transfer) {
  auto* t = static_cast<Transfer*>(transfer->user_data);
  UsbRigController* self = t->owner;
  switch (transfer->status) {
    case LIBUSB_TRANSFER_COMPLETED:
      if (transfer->actual_length > 0) self->handle_packet(transfer);  // 0: a zero-length packet
      break;
    case LIBUSB_TRANSFER_TIMED_OUT:
      // Nothing within the timeout (the device holds back, or the bus is busy): not an error, the
      // transfer goes out again. Whatever part arrived is a whole packet only if it parses.
      ++self->timeouts_;
      if (transfer->actual_length > 0) self->handle_packet(transfer);
      break;
    case LIBUSB_TRANSFER_NO_DEVICE:
      self->lost_ = true;
      break;
    case LIBUSB_TRANSFER_CANCELLED:
      break;
    default:
      self->set_fault("the rig controller " + self->serial_ + "'s stream: bulk transfer status " +
                      std::to_string(static_cast<int>(transfer->status)));
      break;
  }
  const bool again = (transfer->status == LIBUSB_TRANSFER_COMPLETED ||
                      transfer->status == LIBUSB_TRANSFER_TIMED_OUT) &&
                     !self->stopping_ && !self->lost_;
  if (again) {
    const int r = libusb_submit_transfer(transfer);
    if (r == 0) return;
    if (r == LIBUSB_ERROR_NO_DEVICE) self->lost_ = true;
  }
  t->busy = false;
  --self->in_flight_;
}

void UsbRigController::handle_packet(const libusb_transfer* transfer) {
  // The packet's arrival, for the time base: the callback runs as the transfer is reaped.
  const std::int64_t arrived_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(
                                      std::chrono::steady_clock::now().time_since_epoch())
                                      .count();
  std::array<SensorFrame, kMaxFramesPerPacket> frames;
  const PacketDecode decoded = decode_frame_packet(
      std::span<const std::uint8_t>(transfer->buffer, static_cast<std::size_t>(transfer->actual_length)),
      frames);
  if (decoded.error != nullptr) {
    ++malformed_;
    set_fault(std::string("the rig controller ") + serial_ + " sent a malformed frame packet (" +
              decoded.error + "); discarded");
    return;
  }
  for (std::size_t i = 0; i < decoded.frames; ++i) {
    frames[i].host_ns = arrived_ns;
    switch (tracker_.observe(frames[i].sequence)) {
      case SequenceTracker::Verdict::kDeliver:
        if (queue_.try_push(frames[i])) {
          ++received_;
          if (const auto* listener = listener_.load(std::memory_order_acquire)) (*listener)(frames[i]);
        } else {
          ++overflows_;
        }
        device_flags_ = frames[i].flags;
        break;
      case SequenceTracker::Verdict::kLate:
      case SequenceTracker::Verdict::kDuplicate:
        break;
    }
  }
  dropped_ = tracker_.dropped();
  reordered_ = tracker_.late();
  duplicated_ = tracker_.duplicates();
}

int LIBUSB_CALL UsbRigController::on_hotplug(libusb_context*, libusb_device* device,
                                             libusb_hotplug_event event, void* user_data) {
  auto* self = static_cast<UsbRigController*>(user_data);
  if (event == LIBUSB_HOTPLUG_EVENT_DEVICE_ARRIVED) {
    // Only noted: no transfer may run inside a hotplug callback; the event loop rescans.
    self->arrival_seen_ = true;
  } else if (event == LIBUSB_HOTPLUG_EVENT_DEVICE_LEFT && self->connected_) {
    // Hotplug callbacks run inside libusb_handle_events, on the thread that holds libusb's event
    // lock; the handle is only closed by the event thread outside that call, so it is safe here.
    if (self->handle_ != nullptr && libusb_get_device(self->handle_) == device) self->lost_ = true;
  }
  return 0;  // stay registered
}

std::size_t UsbRigController::read_frames(std::span<SensorFrame> out) noexcept {
  std::size_t n = 0;
  while (n < out.size()) {
    auto frame = queue_.try_pop();
    if (!frame) break;
    out[n++] = *frame;
  }
  return n;
}

UsbRigStatus UsbRigController::status() const {
  UsbRigStatus s;
  s.connected = connected_;
  {
    std::lock_guard lock(device_mutex_);
    s.serial = serial_;
  }
  s.frames_received = received_;
  s.frames_dropped = dropped_;
  s.frames_reordered = reordered_;
  s.frames_duplicated = duplicated_;
  s.queue_overflows = overflows_;
  s.malformed_packets = malformed_;
  s.transfer_timeouts = timeouts_;
  s.disconnects = disconnects_;
  s.reconnects = reconnects_;
  s.device_flags = device_flags_;
  std::lock_guard lock(fault_mutex_);
  s.last_fault = last_fault_;
  s.device_fault = device_fault_;
  return s;
}

}  // namespace nibrig::rig::usb
