#include "ui/python/long_call.hpp"

#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

#include "model/io/job_files.hpp"
#include "ui/python/python_log.hpp"

namespace nibrig::ui::python {

namespace py = pybind11;

namespace {

struct Latest {
  std::string step;
  std::size_t done = 0, total = 0;
};

// What the worker and the waiting caller share.
struct Shared {
  std::mutex mutex;
  std::condition_variable changed;
  std::optional<Latest> report;  // not yet passed on
  bool finished = false;
  std::exception_ptr failure;
};

}  // namespace

void run_long_call(const std::function<void(std::stop_token, const Report&)>& work, const py::object& progress) {
  const model::io::JobFiles job;  // one call is one job: what it writes replaces nothing it read
  follow_python_log_level();
  drain_python_log();
  Shared shared;
  std::stop_source stop;
  const Report report = [&shared](const std::string& step, std::size_t done, std::size_t total) {
    std::lock_guard lock(shared.mutex);
    shared.report = Latest{step, done, total};
    shared.changed.notify_one();
  };
  std::jthread worker([&] {
    try {
      work(stop.get_token(), report);
    } catch (...) {
      std::lock_guard lock(shared.mutex);
      shared.failure = std::current_exception();
    }
    std::lock_guard lock(shared.mutex);
    shared.finished = true;
    shared.changed.notify_one();
  });

  std::optional<py::error_already_set> interrupted;  // the first Python exception, kept while the work stops
  for (;;) {
    std::optional<Latest> latest;
    bool finished = false;
    {
      py::gil_scoped_release unlocked;
      std::unique_lock lock(shared.mutex);
      shared.changed.wait_for(lock, std::chrono::milliseconds(50),
                              [&] { return shared.finished || shared.report.has_value(); });
      latest.swap(shared.report);
      finished = shared.finished;
    }
    if (interrupted) {
      if (finished) break;
      continue;  // the work is stopping: nothing more is passed on
    }
    try {
      drain_python_log();
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (latest && !progress.is_none()) progress(latest->step, latest->done, latest->total);
    } catch (py::error_already_set& e) {
      interrupted.emplace(std::move(e));
      stop.request_stop();
      continue;
    }
    if (finished) break;
  }
  {
    py::gil_scoped_release unlocked;
    worker.join();
  }
  drain_python_log();
  if (interrupted) throw std::move(*interrupted);
  if (shared.failure) std::rethrow_exception(shared.failure);
}

}  // namespace nibrig::ui::python
