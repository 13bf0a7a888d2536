// AudioOutput survives its JACK server being killed (SIGKILL, as a crash would) and resumes by
// itself when the server returns, with the same renderer; destruction is safe in every state.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <pthread.h>

#include <atomic>
#include <chrono>
#include <iostream>
#include <memory>
#include <streambuf>
#include <thread>

#include "playback/audio_output.hpp"
#include "tests/playback/cancel_signal.hpp"
#include "tests/playback/jack_recorder.hpp"
#include "tests/playback/jack_stream_settings.hpp"
#include "tests/playback/signal_renderer.hpp"
#include "tests/playback/wait_until.hpp"
#include "tests/support/jack_server.hpp"

namespace nibrig::playback {
namespace {

using namespace std::chrono_literals;
using testing::JackRecorder;
using testing::wait_until;

// A fresh recorder on the (restarted) server that hears the stream's channel 1. The stream's
// port appears only once the output has reopened, so connecting is retried.
std::unique_ptr<JackRecorder> listen_to(const std::string& stream, std::chrono::seconds timeout) {
  auto ear = std::make_unique<JackRecorder>("ear", 1, 0);
  const auto connected =
      wait_until([&] { return ear->connect(stream + ":outport 0", 0); }, timeout);
  return connected.count() >= 0 ? std::move(ear) : nullptr;
}

TEST(AudioOutputRecovery, ReportsAKilledServerAndResumesWhenItReturnsTwice) {
  nibrig::testing::JackServer server;
  testing::SignalRenderer renderer;
  OutputSettings settings = testing::jack_settings("survivor");
  settings.retry_interval = 200ms;
  AudioOutput output(renderer, settings);

  for (int round = 1; round <= 2; ++round) {
    SCOPED_TRACE("round " + std::to_string(round));
    {
      auto ear = listen_to("survivor", 5s);
      ASSERT_NE(ear, nullptr);
      ASSERT_GE(wait_until([&] { return ear->nonsilent_frames() > 4800; }, 5s).count(), 0.0)
          << "no sound before the kill";
      // The recorder dies with the server and must be closed (end of this scope) before the
      // restart: libjack 1.9.21 crashes closing a dead server's client once another client has
      // connected to the new server. AudioOutput closes its own before reopening for that reason.
      server.kill();
      // Bounds: RtAudio's JACK back end learns of the loss when libjack's socket to the server
      // closes (measured ~0.1 s); 2 s leaves room for a loaded machine and the 20 ms poll.
      const auto noticed = wait_until([&] { return output.status() == OutputStatus::lost; }, 2s);
      ASSERT_GE(noticed.count(), 0.0) << "the loss was not reported within 2 s";
      RecordProperty("loss_noticed_ms_round" + std::to_string(round),
                     std::to_string(static_cast<int>(noticed.count() * 1000)));
      EXPECT_THAT(output.last_problem(), ::testing::HasSubstr("closed the stream"));
    }
    const std::uint64_t calls_while_lost = renderer.calls();
    std::this_thread::sleep_for(300ms);  // a few failed reopen attempts against no server
    EXPECT_EQ(output.status(), OutputStatus::lost);
    EXPECT_EQ(renderer.calls(), calls_while_lost) << "the renderer ran without a device";

    server.start();
    const auto started = std::chrono::steady_clock::now();
    // Bounds: one retry interval (0.2 s) plus opening a JACK client; 5 s for a loaded machine.
    const auto resumed = wait_until(
        [&] {
          return output.status() == OutputStatus::running && renderer.calls() > calls_while_lost;
        },
        5s);
    ASSERT_GE(resumed.count(), 0.0)
        << "output did not resume within 5 s: " << output.last_problem();
    auto ear = listen_to("survivor", 5s);
    ASSERT_NE(ear, nullptr);
    ASSERT_GE(wait_until([&] { return ear->nonsilent_frames() > 0; }, 5s).count(), 0.0)
        << "the restarted stream is silent";
    RecordProperty("sound_back_ms_round" + std::to_string(round),
                   std::to_string(std::chrono::duration_cast<std::chrono::milliseconds>(
                                      std::chrono::steady_clock::now() - started)
                                      .count()));
  }
  const OutputStats stats = output.stats();
  EXPECT_EQ(stats.losses, 2u);
  EXPECT_EQ(stats.reconnects, 2u);
  EXPECT_TRUE(output.last_problem().empty()) << output.last_problem();
}

TEST(AudioOutputRecovery, DestructionIsSafeWhileTheDeviceIsLost) {
  nibrig::testing::JackServer server;
  testing::SignalRenderer renderer;
  auto output = std::make_unique<AudioOutput>(renderer, testing::jack_settings("lost"));
  server.kill();
  ASSERT_GE(wait_until([&] { return output->status() == OutputStatus::lost; }, 2s).count(), 0.0);
  std::this_thread::sleep_for(250ms);  // inside the retry loop
  const auto start = std::chrono::steady_clock::now();
  output.reset();
  // Bounded by one reopen attempt against no server (fails at once) and a poll: well under 2 s.
  EXPECT_LT(std::chrono::steady_clock::now() - start, 2s);
}

TEST(AudioOutputRecovery, DestructionIsSafeRightAfterTheServerDies) {
  nibrig::testing::JackServer server;
  testing::SignalRenderer renderer;
  auto output = std::make_unique<AudioOutput>(renderer, testing::jack_settings("dying"));
  ASSERT_GE(wait_until([&] { return renderer.calls() > 10; }, 5s).count(), 0.0);
  server.kill();
  // Before the supervisor has noticed: the stream may be mid-close by RtAudio's own thread.
  output.reset();
  SUCCEED() << "no crash, no hang, no sanitizer report";
}

TEST(AudioOutputRecovery, DestructionIsSafeWhileReopening) {
  nibrig::testing::JackServer server;
  testing::SignalRenderer renderer;
  OutputSettings settings = testing::jack_settings("reopening");
  settings.retry_interval = 20ms;  // the supervisor spends most of its time opening
  auto output = std::make_unique<AudioOutput>(renderer, settings);
  server.kill();
  ASSERT_GE(wait_until([&] { return output->status() == OutputStatus::lost; }, 2s).count(), 0.0);
  server.start();  // returns once clients can connect: the supervisor is at it every 20 ms
  output.reset();
  SUCCEED() << "no crash, no hang, no sanitizer report";
}

// Discards what is written to it; lets the held cancel signal in at a flush, as if the cancel had
// arrived then.
class ReleaseOnFlush : public std::streambuf {
 protected:
  int_type overflow(int_type c) override { return traits_type::not_eof(c); }
  int sync() override {
    testing::hold_cancel_signal(false);
    return 0;
  }
};

std::atomic<bool> message_held{false};
std::atomic<bool> message_cancelled{false};
std::atomic<bool> message_printed{false};

// RtAudio 5.2's JACK shutdown handler, on libjack's notification thread (asynchronously
// cancellable), prints this while the closing thread it started cancels that thread.
void* shutdown_message(void*) {
  pthread_setcanceltype(PTHREAD_CANCEL_ASYNCHRONOUS, nullptr);
  testing::hold_cancel_signal(true);
  message_held.store(true, std::memory_order_release);
  while (!message_cancelled.load(std::memory_order_acquire)) std::this_thread::yield();
  std::cerr << "\nRtApiJack: the Jack server is shutting down this client ... stream stopped and "
               "closed!!\n"
            << std::endl;
  message_printed.store(true, std::memory_order_release);
  return nullptr;
}

// Opening a JACK output takes unitbuf off std::cerr: with it, each insertion flushes in
// ostream::sentry's noexcept destructor, where such a cancel ends the process ("terminate called
// without an active exception").
TEST(AudioOutputRecovery, ACancelDuringRtAudiosShutdownMessageEndsThatThreadAlone) {
  nibrig::testing::JackServer server;
  testing::SignalRenderer renderer;
  AudioOutput output(renderer, testing::jack_settings("message"));
  ReleaseOnFlush sink;
  struct Restore {
    std::streambuf* buffer;
    ~Restore() { std::cerr.rdbuf(buffer); }  // which clears the badbit a cancelled insertion sets
  } restore{std::cerr.rdbuf(&sink)};
  pthread_t thread;
  ASSERT_EQ(pthread_create(&thread, nullptr, &shutdown_message, nullptr), 0);
  while (!message_held.load(std::memory_order_acquire)) std::this_thread::yield();
  ASSERT_EQ(pthread_cancel(thread), 0);  // enabled and asynchronous: the signal is sent, and held
  message_cancelled.store(true, std::memory_order_release);
  ASSERT_EQ(pthread_join(thread, nullptr), 0);
  EXPECT_FALSE(message_printed.load(std::memory_order_acquire)) << "the cancellation was lost";
}

}  // namespace
}  // namespace nibrig::playback
