// The library's exceptions as Python's, with the message the command line prints (file, place,
// what was expected): bad input is ValueError; a file that is missing or cannot be opened or
// written, and a device, OSError (FileNotFoundError when the file is not there); a long call
// stopped by its stop token, KeyboardInterrupt.
#pragma once

#include <pybind11/pybind11.h>

namespace nibrig::ui::python {

void register_error_translation();

}  // namespace nibrig::ui::python
