#include "ui/python/python_log.hpp"

#include <pybind11/pybind11.h>
#include <spdlog/sinks/base_sink.h>
#include <spdlog/spdlog.h>

#include <deque>
#include <memory>
#include <mutex>
#include <string>

namespace nibrig::ui::python {

namespace py = pybind11;

namespace {

struct Message {
  int level = 20;  // Python's: DEBUG 10, INFO 20, WARNING 30, ERROR 40, CRITICAL 50
  std::string text;
};

// A long call logs a line per step at most; a queue this long outlasts any burst between drains.
constexpr std::size_t kMostQueued = 10000;

int python_level(spdlog::level::level_enum level) {
  switch (level) {
    case spdlog::level::trace:
    case spdlog::level::debug:
      return 10;
    case spdlog::level::info:
      return 20;
    case spdlog::level::warn:
      return 30;
    case spdlog::level::err:
      return 40;
    default:
      return 50;
  }
}

class QueueSink final : public spdlog::sinks::base_sink<std::mutex> {
 public:
  std::deque<Message> take(std::size_t& dropped) {
    std::lock_guard lock(mutex_);
    dropped = dropped_;
    dropped_ = 0;
    return std::exchange(queue_, {});
  }

 protected:
  void sink_it_(const spdlog::details::log_msg& msg) override {
    if (queue_.size() >= kMostQueued) {
      ++dropped_;
      return;
    }
    queue_.push_back(
        {python_level(msg.level), std::string(msg.payload.data(), msg.payload.size())});
  }
  void flush_() override {}

 private:
  std::deque<Message> queue_;
  std::size_t dropped_ = 0;
};

std::shared_ptr<QueueSink>& queue() {
  static std::shared_ptr<QueueSink> sink;
  return sink;
}

}  // namespace

void install_python_log() {
  queue() = std::make_shared<QueueSink>();
  auto logger = std::make_shared<spdlog::logger>("nibrig", queue());
  logger->set_level(spdlog::level::info);
  spdlog::set_default_logger(logger);
}

void follow_python_log_level() {
  const int level = py::module_::import("logging")
                        .attr("getLogger")("nibrig")
                        .attr("getEffectiveLevel")()
                        .cast<int>();
  spdlog::default_logger()->set_level(level <= 10   ? spdlog::level::debug
                                      : level <= 20 ? spdlog::level::info
                                      : level <= 30 ? spdlog::level::warn
                                      : level <= 40 ? spdlog::level::err
                                                    : spdlog::level::critical);
}

void drain_python_log() {
  if (!queue()) return;
  std::size_t dropped = 0;
  const std::deque<Message> messages = queue()->take(dropped);
  if (messages.empty() && dropped == 0) return;
  const py::object logger = py::module_::import("logging").attr("getLogger")("nibrig");
  for (const auto& m : messages) logger.attr("log")(m.level, "%s", m.text);
  if (dropped > 0)
    logger.attr("warning")(
        "%d log messages were dropped: more came between two looks than the queue holds", dropped);
}

ReleasedGil::ReleasedGil() {
  follow_python_log_level();
  released_.emplace();
}

ReleasedGil::~ReleasedGil() {
  released_.reset();
  try {
    drain_python_log();
  } catch (py::error_already_set& e) {
    // A logging handler that raised: its error cannot leave a destructor; Python reports it as
    // unraisable, as it does for one in __del__.
    e.discard_as_unraisable(__func__);
  }
}

}  // namespace nibrig::ui::python
