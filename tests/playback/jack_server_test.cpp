// The test JACK server itself: starts, accepts clients, dies on kill and comes back on start.
#include "tests/support/jack_server.hpp"

#include <gtest/gtest.h>
#include <jack/jack.h>

namespace nibrig::testing {
namespace {

bool connects(const std::string& server) {
  jack_status_t status{};
  jack_client_t* c = jack_client_open(
      "probe", static_cast<jack_options_t>(JackNoStartServer | JackServerName), &status,
      server.c_str());
  if (!c) return false;
  const bool right_rate = jack_get_sample_rate(c) == 48000 && jack_get_buffer_size(c) == 64;
  jack_client_close(c);
  return right_rate;
}

TEST(JackServer, StartsKillsAndRestartsUnderItsName) {
  JackServer server;
  EXPECT_TRUE(connects(server.name())) << server.log();
  server.kill();
  EXPECT_FALSE(connects(server.name()));
  server.start();
  EXPECT_TRUE(connects(server.name())) << server.log();
}

}  // namespace
}  // namespace nibrig::testing
