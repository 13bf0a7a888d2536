#include "tests/support/jack_server.hpp"

#include <fcntl.h>
#include <jack/jack.h>
#include <pthread.h>
#include <sched.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

extern char** environ;

namespace nibrig::testing {
namespace {

std::string unique_name() {
  static std::atomic<int> counter{0};
  return "nibrig-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
}

bool client_can_connect(const std::string& server) {
  jack_status_t status{};
  jack_client_t* client = jack_client_open(
      "nibrig-probe", static_cast<jack_options_t>(JackNoStartServer | JackServerName), &status,
      server.c_str());
  if (client == nullptr) return false;
  jack_client_close(client);
  return true;
}

// Whether this process may schedule a thread SCHED_FIFO (root, CAP_SYS_NICE or an rtprio limit),
// tried on a thread of its own so that nothing else changes class.
bool realtime_allowed() {
  static const bool allowed = [] {
    bool ok = false;
    std::thread probe([&ok] {
      sched_param param{};
      param.sched_priority = sched_get_priority_min(SCHED_FIFO);
      ok = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param) == 0;
    });
    probe.join();
    return ok;
  }();
  return allowed;
}

void quiet_jack_errors() {
  // libjack prints "Cannot connect to server socket" on every failed probe; the log says enough.
  jack_set_error_function([](const char*) {});
  jack_set_info_function([](const char*) {});
}

}  // namespace

JackServer::JackServer(const JackServerSettings& settings)
    : settings_(settings), name_(unique_name()) {
  log_file_ = std::filesystem::temp_directory_path() / (name_ + ".log");
  ::setenv("JACK_DEFAULT_SERVER", name_.c_str(), 1);
  ::setenv("JACK_NO_AUDIO_RESERVATION", "1", 1);
  quiet_jack_errors();
  start();
}

JackServer::~JackServer() {
  if (pid_ > 0) {
    stop();
  } else if (left_registered_) {
    // Only a server of the same name reclaims a killed server's registry slot: start it once
    // more and stop it cleanly, or every killed server would take one of the 8 slots for good.
    try {
      start();
      stop();
    } catch (const std::exception&) {
    }
  }
  std::error_code ignored;
  std::filesystem::remove(log_file_, ignored);
}

std::string JackServer::log() const {
  std::ifstream in(log_file_);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void JackServer::start() {
  if (pid_ > 0) return;
  const std::string rate = std::to_string(settings_.sample_rate);
  const std::string period = std::to_string(settings_.period);
  // Real-time where the machine allows it, as a user's audio setup runs: the dummy driver's cycle
  // and every client's process thread then take the CPU from the build and the other tests. Without
  // it a loaded machine delayed cycles by thousands of xruns per calibration (the sweeps agreed to
  // only 21-34 dB with two compilers running; with it, the first attempt measured the chain within
  // 0.13 dB), and in CI a tap's area said that the dummy clock had run 13 % slow.
  std::vector<std::string> args = {"jackd", "-n", name_};
  if (realtime_allowed()) {
    args.insert(args.end(), {"--realtime", "-P", "70"});
  } else {
    args.emplace_back("--no-realtime");
  }
  if (settings_.loopback_ports > 0) {
    args.insert(args.end(), {"-L", std::to_string(settings_.loopback_ports)});
  }
  args.insert(args.end(), {"-d", "dummy", "-r", rate, "-p", period});
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log_file_.c_str(), O_WRONLY | O_CREAT | O_APPEND,
                                   0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  const int failed = posix_spawnp(&pid_, "jackd", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (failed != 0) {
    pid_ = -1;
    throw std::runtime_error("cannot start jackd (is jackd2 installed?)");
  }
  left_registered_ = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (!client_can_connect(name_)) {
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      throw std::runtime_error("jackd exited at start:\n" + log());
    }
    if (std::chrono::steady_clock::now() > deadline) {
      kill();
      throw std::runtime_error("jackd did not accept clients within 10 s:\n" + log());
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

void JackServer::kill() {
  if (pid_ <= 0) return;
  ::kill(pid_, SIGKILL);
  int status = 0;
  ::waitpid(pid_, &status, 0);
  pid_ = -1;
  left_registered_ = true;
}

void JackServer::stop() {
  if (pid_ <= 0) return;
  ::kill(pid_, SIGTERM);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  int status = 0;
  while (::waitpid(pid_, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      kill();
      return;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  pid_ = -1;
}

}  // namespace nibrig::testing
