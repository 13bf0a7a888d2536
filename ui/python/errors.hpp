// The library's exceptions as Python's, with the message the command line prints (file, place,
// what was expected): bad input is ValueError; a file that is missing or cannot be opened or
// written, and a device, OSError (FileNotFoundError when the file is not there); a long call
// stopped by its stop token, KeyboardInterrupt.
#pragma once

#include <pybind11/pybind11.h>

#include <stdexcept>

namespace nibrig::ui::python {

void register_error_translation();

// A refusal of the system's that a library call reports as a plain std::runtime_error (a device
// missing or gone, a folder that exists): a face that knows it is one rethrows it as this, OSError.
class SystemRefusal : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace nibrig::ui::python
