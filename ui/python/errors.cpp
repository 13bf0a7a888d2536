#include "ui/python/errors.hpp"

#include <filesystem>
#include <stdexcept>

#include "model/io/atomic_file.hpp"
#include "model/io/finite_output.hpp"
#include "model/io/format_error.hpp"
#include "model/numeric/cancellation.hpp"
#include "playback/device_error.hpp"

namespace nibrig::ui::python {

void register_error_translation() {
  pybind11::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const model::numeric::Cancelled& e) {
      PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
    } catch (const model::io::FormatError& e) {
      // A reader names its file: one that is not there, or cannot be opened, is the file's fault, not
      // its content's.
      std::error_code ec;
      const bool missing = !e.file().empty() && !std::filesystem::exists(e.file(), ec);
      const bool unopened = std::string(e.what()).find("cannot open") != std::string::npos;
      PyErr_SetString(missing ? PyExc_FileNotFoundError : unopened ? PyExc_OSError : PyExc_ValueError, e.what());
    } catch (const model::io::OutputFileError& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const std::filesystem::filesystem_error& e) {  // a folder that cannot be made, say
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const SystemRefusal& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const playback::DeviceError& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const model::io::UnwritableOutput& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const std::invalid_argument& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const std::domain_error& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const std::out_of_range& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
}

}  // namespace nibrig::ui::python
