// A bounded single-producer single-consumer queue: how control threads hand speed and force updates
// and voice swaps to the audio thread (ARCHITECTURE.md, "Real-time rules"). Storage is allocated once at
// construction; push and pop never allocate, lock or throw, and each touches one atomic the other
// side writes.
#pragma once

#include <atomic>
#include <cstddef>
#include <memory>
#include <new>
#include <optional>
#include <stdexcept>
#include <type_traits>

namespace nibrig::rt {

template <typename T>
class SpscQueue {
  static_assert(std::is_trivially_copyable_v<T>,
                "queue items are copied on the audio thread: they must be trivially copyable");

 public:
  // Holds up to `capacity` items (rounded up to a power of two so that indices wrap with a mask).
  // Throws std::invalid_argument for capacity 0; this runs on a control thread, never the audio one.
  explicit SpscQueue(std::size_t capacity) {
    if (capacity == 0) throw std::invalid_argument("an SPSC queue needs a capacity of at least 1");
    std::size_t size = 1;
    while (size < capacity) size <<= 1;
    mask_ = size - 1;
    slots_ = std::make_unique<T[]>(size);
  }

  std::size_t capacity() const noexcept { return mask_ + 1; }

  // Producer only. False when full: the item is not stored (the caller decides whether an update
  // may be dropped; for speed, the next update supersedes it anyway).
  bool try_push(const T& item) noexcept {
    const std::size_t head = head_.load(std::memory_order_relaxed);
    if (head - tail_cache_ > mask_) {
      tail_cache_ = tail_.load(std::memory_order_acquire);
      if (head - tail_cache_ > mask_) return false;
    }
    slots_[head & mask_] = item;
    head_.store(head + 1, std::memory_order_release);
    return true;
  }

  // Consumer only. Empty optional when there is nothing to take.
  std::optional<T> try_pop() noexcept {
    const std::size_t tail = tail_.load(std::memory_order_relaxed);
    if (tail == head_cache_) {
      head_cache_ = head_.load(std::memory_order_acquire);
      if (tail == head_cache_) return std::nullopt;
    }
    const T item = slots_[tail & mask_];
    tail_.store(tail + 1, std::memory_order_release);
    return item;
  }

  // Consumer only: the newest item, dropping older ones (a control value where only the latest
  // matters). Empty when the queue was empty.
  std::optional<T> pop_latest() noexcept {
    std::optional<T> latest;
    while (auto item = try_pop()) latest = item;
    return latest;
  }

 private:
  // Producer and consumer indices on separate cache lines so that the two threads do not share one.
  static constexpr std::size_t kLine = 64;
  alignas(kLine) std::atomic<std::size_t> head_{0};  // written by the producer
  std::size_t tail_cache_ = 0;                       // the producer's last view of tail_
  alignas(kLine) std::atomic<std::size_t> tail_{0};  // written by the consumer
  std::size_t head_cache_ = 0;                       // the consumer's last view of head_
  alignas(kLine) std::size_t mask_ = 0;
  std::unique_ptr<T[]> slots_;
};

}  // namespace nibrig::rt
