// The library's log (spdlog) through Python's `logging`, logger "nibrig": a script or notebook
// sees it as any other library's, filtered and formatted by its own handlers. Messages come from
// any thread, so they wait in a queue until a thread holding the GIL passes them on: a long call
// does so while it waits and when it ends, and so does every call that releases the GIL through
// ReleasedGil, when it takes the GIL back.
#pragma once

#include <pybind11/pybind11.h>

#include <optional>

namespace nibrig::ui::python {

// Makes the queue the default logger's only sink. Once, when the module is imported.
void install_python_log();

// Sets the library's threshold to the "nibrig" logger's effective level, so that what Python
// would drop is not formatted. With the GIL held.
void follow_python_log_level();

// Passes the queued messages to logging.getLogger("nibrig"), with the GIL held; says so when the
// queue was full and messages were dropped.
void drain_python_log();

// The GIL released for library work, as pybind11::gil_scoped_release; when it is taken back, what
// the work logged goes to Python's logging. Made with the GIL held.
class ReleasedGil {
 public:
  ReleasedGil();
  ~ReleasedGil();
  ReleasedGil(const ReleasedGil&) = delete;
  ReleasedGil& operator=(const ReleasedGil&) = delete;

 private:
  std::optional<pybind11::gil_scoped_release> released_;
};

}  // namespace nibrig::ui::python
