// Accounts for every sequence number of the frame stream (PROTOCOL.md "The frame stream"): which
// frames to deliver, and how many were dropped, arrived late (reordered) or twice. Runs on
// whichever thread handles libusb's events, so it neither allocates nor locks.
#pragma once

#include <cstdint>

namespace nibrig::rig::usb {

class SequenceTracker {
 public:
  enum class Verdict { kDeliver, kLate, kDuplicate };

  // The next frame after a (re)start is the new baseline: frames the device sampled while the host
  // was not listening are not losses of the stream.
  void restart() { started_ = false; }

  // A frame ahead of the expected one counts the gap as dropped; one behind it that was never seen
  // (within the last 64) was reordered: it is taken off the dropped count but not delivered, so the
  // consumer's frames stay in time order; one already seen is a duplicate.
  Verdict observe(std::uint32_t sequence) {
    if (!started_) {
      started_ = true;
      next_ = sequence + 1;
      seen_ = 1;
      return Verdict::kDeliver;
    }
    const auto ahead = static_cast<std::int32_t>(sequence - next_);  // wraps at 2^32 as the wire does
    if (ahead >= 0) {
      dropped_ += static_cast<std::uint64_t>(ahead);
      const std::uint32_t shift = static_cast<std::uint32_t>(ahead) + 1;
      seen_ = shift >= 64 ? 1 : (seen_ << shift) | 1;
      next_ = sequence + 1;
      return Verdict::kDeliver;
    }
    // behind: bit k of seen_ is sequence next_ - 1 - k.
    const std::uint32_t back = next_ - 1 - sequence;
    if (back < 64 && (seen_ & (std::uint64_t{1} << back)) != 0) {
      ++duplicates_;
      return Verdict::kDuplicate;
    }
    if (back < 64) {
      seen_ |= std::uint64_t{1} << back;
      if (dropped_ > 0) --dropped_;
    }
    ++late_;
    return Verdict::kLate;
  }

  std::uint64_t dropped() const { return dropped_; }
  std::uint64_t late() const { return late_; }
  std::uint64_t duplicates() const { return duplicates_; }

 private:
  bool started_ = false;
  std::uint32_t next_ = 0;
  std::uint64_t seen_ = 0;  // the last 64 sequence numbers below next_, bit 0 = next_ - 1
  std::uint64_t dropped_ = 0;
  std::uint64_t late_ = 0;
  std::uint64_t duplicates_ = 0;
};

}  // namespace nibrig::rig::usb
