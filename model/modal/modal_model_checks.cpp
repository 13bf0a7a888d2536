#include "model/modal/modal_model_checks.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace nibrig::model::modal {
namespace {

[[noreturn]] void fail(const std::string& caller, const std::string& problem) {
  throw std::invalid_argument(caller + ": " + problem);
}

std::string entry(const char* field, std::size_t index, double value) {
  return std::string("ModalModel ") + field + "[" + std::to_string(index) +
         "] = " + format_number(value);
}

}  // namespace

std::string format_number(double value) {
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

void check_modal_model(const ModalModel& model, const std::string& caller) {
  const std::size_t n = model.omega.size();
  if (n == 0) fail(caller, "ModalModel has no modes (omega is empty)");
  check_same_size(model.zeta.size(), n, "ModalModel zeta (one per mode, as omega)", caller);
  check_same_size(model.input.size(), n, "ModalModel input b (one per mode, as omega)", caller);
  check_same_size(model.output.size(), n, "ModalModel output c (one per mode, as omega)", caller);
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(model.omega[i]) || model.omega[i] <= 0.0) {
      fail(caller, entry("omega", i, model.omega[i]) + " rad/s: must be finite and > 0");
    }
    if (!std::isfinite(model.zeta[i]) || model.zeta[i] < 0.0) {
      fail(caller, entry("zeta", i, model.zeta[i]) + ": must be finite and >= 0");
    }
    if (!std::isfinite(model.input[i])) {
      fail(caller, entry("input", i, model.input[i]) + ": must be finite");
    }
    if (!std::isfinite(model.output[i])) {
      fail(caller, entry("output", i, model.output[i]) + ": must be finite");
    }
  }
}

void check_sample_rate(double sample_rate, const std::string& caller) {
  if (!std::isfinite(sample_rate) || sample_rate <= 0.0) {
    fail(caller, "sample rate " + format_number(sample_rate) + " Hz: must be finite and > 0");
  }
}

void check_finite(double value, const std::string& what, const std::string& caller) {
  if (!std::isfinite(value)) fail(caller, what + " = " + format_number(value) + ": must be finite");
}

void check_same_size(std::size_t size, std::size_t expected, const std::string& what,
                     const std::string& caller) {
  if (size != expected) {
    fail(caller,
         what + " has " + std::to_string(size) + " entries, expected " + std::to_string(expected));
  }
}

}  // namespace nibrig::model::modal
