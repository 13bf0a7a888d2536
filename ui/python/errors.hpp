// The library's exceptions as Python's, with the message the command line prints (file, place,
// what was expected): bad input is ValueError; a file that is missing or cannot be opened or
// written, and a device, OSError (FileNotFoundError when the file is not there); a long call
// stopped by its stop token, KeyboardInterrupt.
#pragma once

#include <pybind11/pybind11.h>

#include <stdexcept>

#include "model/io/atomic_file.hpp"
#include "model/io/finite_output.hpp"
#include "model/io/format_error.hpp"
#include "model/numeric/cancellation.hpp"

namespace nibrig::ui::python {

void register_error_translation();

// A refusal of the system's that a library call reports as a plain std::runtime_error (a device
// missing or gone, a folder that exists): a face that knows it is one rethrows it as this, OSError.
class SystemRefusal : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Runs a call of the rig's, whose device that is missing or gone and whose session folder that
// exists or cannot be written come as plain std::runtime_error: those become SystemRefusal; the
// library's own types pass as they are.
template <typename Call>
auto system_refusals(Call&& call) {
  try {
    return call();
  } catch (const model::io::FormatError&) {
    throw;
  } catch (const model::numeric::Cancelled&) {
    throw;
  } catch (const model::io::OutputFileError&) {
    throw;
  } catch (const model::io::UnwritableOutput&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw SystemRefusal(e.what());
  }
}

}  // namespace nibrig::ui::python
