// A bounded single-producer single-consumer ring of float samples moved in blocks: how the audio
// callback hands captured input (an accelerometer, a calibration sweep's response) to a control
// thread. Storage is allocated once at construction; push and pop never allocate, lock or throw.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <memory>
#include <stdexcept>

namespace nibrig::playback {

class SampleRing {
 public:
  // Holds up to `capacity` samples (rounded up to a power of two so that indices wrap with a mask).
  explicit SampleRing(std::size_t capacity) {
    if (capacity == 0) throw std::invalid_argument("a sample ring needs a capacity of at least 1");
    std::size_t size = 1;
    while (size < capacity) size <<= 1;
    mask_ = size - 1;
    data_ = std::make_unique<float[]>(size);
  }

  std::size_t capacity() const noexcept { return mask_ + 1; }

  // Producer only. Stores as many of the `count` samples as fit and returns how many; the caller
  // counts the rest as dropped (the newest are lost, so what was stored stays contiguous).
  std::size_t push(const float* samples, std::size_t count) noexcept {
    const std::size_t head = head_.load(std::memory_order_relaxed);
    const std::size_t tail = tail_.load(std::memory_order_acquire);
    const std::size_t n = std::min(count, capacity() - (head - tail));
    copy_in(head, samples, n);
    head_.store(head + n, std::memory_order_release);
    return n;
  }

  // Consumer only. Takes up to `max` samples and returns how many were taken.
  std::size_t pop(float* out, std::size_t max) noexcept {
    const std::size_t tail = tail_.load(std::memory_order_relaxed);
    const std::size_t head = head_.load(std::memory_order_acquire);
    const std::size_t n = std::min(max, head - tail);
    copy_out(tail, out, n);
    tail_.store(tail + n, std::memory_order_release);
    return n;
  }

  // Either side: samples waiting (exact for the consumer, a lower bound for the producer).
  std::size_t size() const noexcept {
    return head_.load(std::memory_order_acquire) - tail_.load(std::memory_order_acquire);
  }

 private:
  void copy_in(std::size_t at, const float* from, std::size_t n) noexcept {
    const std::size_t start = at & mask_;
    const std::size_t first = std::min(n, capacity() - start);
    std::copy_n(from, first, data_.get() + start);
    std::copy_n(from + first, n - first, data_.get());
  }
  void copy_out(std::size_t at, float* to, std::size_t n) const noexcept {
    const std::size_t start = at & mask_;
    const std::size_t first = std::min(n, capacity() - start);
    std::copy_n(data_.get() + start, first, to);
    std::copy_n(data_.get(), n - first, to + first);
  }

  // Producer and consumer indices on separate cache lines so that the two threads do not share one.
  static constexpr std::size_t kLine = 64;
  alignas(kLine) std::atomic<std::size_t> head_{0};  // written by the producer
  alignas(kLine) std::atomic<std::size_t> tail_{0};  // written by the consumer
  alignas(kLine) std::size_t mask_ = 0;
  std::unique_ptr<float[]> data_;
};

}  // namespace nibrig::playback
