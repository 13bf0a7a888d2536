// A long library call from Python (a fit, a bootstrap, a grid, a capture): the work runs on a
// thread of its own while the calling thread, the GIL released, waits for it; every 50 ms, and
// whenever the work reports progress, the caller takes the GIL back to pass the progress to the
// Python callable and to look for Ctrl-C. On KeyboardInterrupt (or an exception the callable
// raises) the work is asked to stop through its stop token and joined; its Cancelled is then the
// Python exception that stopped it, and nothing it would have written is written.
#pragma once

#include <pybind11/pybind11.h>

#include <functional>
#include <stop_token>
#include <string>

namespace nibrig::ui::python {

// What the work reports: a step's name, how many of it are done, of how many. From any thread.
using Report = std::function<void(const std::string& step, std::size_t done, std::size_t total)>;

// Runs work(stop, report) and returns when it has ended. `progress` is None or a callable taking
// (step: str, done: int, total: int); it is called on the calling thread with the GIL held, with
// the latest report (a report that a newer one overtakes before the caller wakes is skipped).
// Rethrows what the work threw, or throws pybind11::error_already_set for KeyboardInterrupt or an
// exception the callable raised.
void run_long_call(const std::function<void(std::stop_token, const Report&)>& work,
                   const pybind11::object& progress);

}  // namespace nibrig::ui::python
