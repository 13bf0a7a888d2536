// A private JACK server with the dummy driver for one test: a real jackd process (no sound card
// needed) under a name of its own, so suites running in parallel never share a server. Clients in
// this process reach it through JACK_DEFAULT_SERVER, which the constructor sets.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <string>

namespace nibrig::testing {

struct JackServerSettings {
  int sample_rate = 48000;
  int period = 64;
  // Ports of JACK's own loopback driver (jackd -L): what is played to loopback:playback_N comes
  // back at loopback:capture_N a cycle later. 0: none.
  int loopback_ports = 0;
};

class JackServer {
 public:
  // Starts `jackd -n <unique name> [--realtime -P 70 | --no-realtime] [-L <loopback ports>]
  // -d dummy -r <rate> -p <period>` (real-time when this process may use SCHED_FIFO) and waits
  // until a client can connect (up to 10 s). Throws std::runtime_error with the server's log on failure.
  explicit JackServer(const JackServerSettings& settings = {});
  ~JackServer();
  JackServer(const JackServer&) = delete;
  JackServer& operator=(const JackServer&) = delete;

  const std::string& name() const { return name_; }
  // The server's output so far (its log file): for failure messages.
  std::string log() const;
  bool running() const { return pid_ > 0; }

  // SIGKILL, as a crash or a pulled device would; waits for the process to go.
  void kill();
  // Starts it again under the same name and waits until a client can connect.
  void start();

 private:
  // SIGTERM, so that jackd leaves the machine-wide server registry; SIGKILL after 5 s.
  void stop();

  JackServerSettings settings_;
  std::string name_;
  std::filesystem::path log_file_;
  pid_t pid_ = -1;
  // A killed jackd keeps its slot in jack2's server registry (/dev/shm/jack-shm-registry, 8 slots
  // for the whole machine) until a server of the same name starts again.
  bool left_registered_ = false;
};

}  // namespace nibrig::testing
