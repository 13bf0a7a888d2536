// The firmware's frame stream on the simulated chip, in simulated time, to a host that always has a
// bulk transfer waiting: every sequence number arrives, the frame period's jitter, and the time from
// a frame's sample to its packet's arrival.
//
// What the numbers include and what they do not. A frame's device time is its nominal sampling
// instant (the timer's compare match); the frame interrupt runs a few cycles later, when the chip
// finishes its instruction or another interrupt, and that delay is the sampling instant's jitter
// (the boundary of the ADC means' window). The latency runs from that nominal instant to the
// simulated instant the host read the packet's last USB packet: the firmware's batching (a packet
// leaves with 8 frames, or when its oldest waited 4 ms), its main loop, and this harness's look at
// the bus every 25 us, which stands in for a host controller polling the endpoint. It does not
// include a real bus's 1 ms frame schedule, the kernel or libusb: the host's timeline adds those
// (rig/clock_fit.hpp fits them out).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "tests/rig/usb/board_host.hpp"

namespace nibrig::rig::usb::testing {
namespace {

struct Spread {
  double mean = 0.0, sd = 0.0, worst = 0.0;
};

Spread spread_of(const std::vector<double>& v) {
  Spread s;
  if (v.empty()) return s;
  for (double x : v) s.mean += x;
  s.mean /= static_cast<double>(v.size());
  for (double x : v) s.sd += (x - s.mean) * (x - s.mean);
  s.sd = std::sqrt(s.sd / static_cast<double>(v.size()));
  s.worst = *std::max_element(v.begin(), v.end());
  return s;
}

void record_spread(const std::string& key, const Spread& s) {
  ::testing::Test::RecordProperty(key + "_mean_us", std::to_string(s.mean));
  ::testing::Test::RecordProperty(key + "_sd_us", std::to_string(s.sd));
  ::testing::Test::RecordProperty(key + "_worst_us", std::to_string(s.worst));
}

void check_stream_at(unsigned rate_hz, double seconds) {
  BoardHost host;
  host.require_out(Request::kSetFrameRate, static_cast<std::uint16_t>(rate_hz));
  host.board().record_frame_interrupts();
  host.require_out(Request::kSetStreaming, 1);
  host.run_us(seconds * 1e6);
  const auto& frames = host.frames();
  const std::uint64_t period_us = 1'000'000 / rate_hz;

  // Every frame, in order, each one period after the last: nothing lost while the host keeps up.
  ASSERT_FALSE(frames.empty());
  const std::uint64_t spanned = frames.back().frame.sequence - frames.front().frame.sequence + 1;
  EXPECT_EQ(spanned - frames.size(), 0u) << "frames lost of " << spanned;
  ASSERT_GE(frames.size(), static_cast<std::size_t>(0.99 * seconds * rate_hz));
  for (std::size_t i = 1; i < frames.size(); ++i) {
    ASSERT_EQ(frames[i].frame.sequence, frames[i - 1].frame.sequence + 1) << "at frame " << i;
    ASSERT_EQ(frames[i].frame.device_time_us - frames[i - 1].frame.device_time_us, period_us) << "at frame " << i;
  }

  // The frame interrupt's entry after its compare match: the sampling instant's jitter.
  std::vector<double> entry_us;
  const std::uint64_t first_due = host.board().clock_start_cycle() + frames.front().frame.device_time_us * 16;
  for (const FrameInterrupt& f : host.board().frame_interrupts()) {
    if (f.due_cycle >= first_due) entry_us.push_back(static_cast<double>(f.entry_cycle - f.due_cycle) / 16.0);
  }
  ASSERT_GE(entry_us.size(), frames.size());
  // The sample's arrival on the host.
  std::vector<double> latency_us;
  for (const ReceivedFrame& f : frames) latency_us.push_back(f.received_us - host.sim_us_at_device_us(f.frame.device_time_us));
  const Spread entry = spread_of(entry_us), latency = spread_of(latency_us);
  std::printf("%4u Hz, %zu frames: sampling instant late by %.2f us mean, %.2f sd, %.2f worst; "
              "sample to host %.0f us mean, %.0f sd, %.0f worst\n",
              rate_hz, frames.size(), entry.mean, entry.sd, entry.worst, latency.mean, latency.sd, latency.worst);
  const std::string key = "at_" + std::to_string(rate_hz) + "_hz";
  record_spread(key + "_sampling_delay", entry);
  record_spread(key + "_sample_to_host", latency);

  // A frame's window of ADC conversions (104 us each) starts and ends within a few cycles of its
  // nominal instant: 20 us late at worst moves its boundary by a fifth of one conversion.
  EXPECT_LT(entry.worst, 20.0);
  EXPECT_GE(*std::min_element(entry_us.begin(), entry_us.end()), 0.0);
  // The firmware starts a packet when it holds 8 frames or its oldest has waited 4 ms, then hands
  // it to the endpoint 64 bytes a pass of its main loop (up to 4 of them, a pass taking up to
  // 0.5 ms when the speed loop runs in it): no frame should arrive later than that wait, a frame
  // period and 2 ms.
  const double design_bound_us = std::min(4000.0, 8.0 * static_cast<double>(period_us)) +
                                 static_cast<double>(period_us) + 2000.0;
  EXPECT_LT(latency.worst, design_bound_us);
  EXPECT_LT(latency.worst, 10'000.0);  // PROTOCOL.md's bound
  EXPECT_GT(*std::min_element(latency_us.begin(), latency_us.end()), 0.0);  // never before its sample
}

TEST(BoardStream, EveryFrameArrivesAtOneKilohertz) { check_stream_at(1000, 2.0); }

TEST(BoardStream, EveryFrameArrivesAtThreeKilohertz) { check_stream_at(3000, 2.0); }  // its highest rate


}  // namespace
}  // namespace nibrig::rig::usb::testing
