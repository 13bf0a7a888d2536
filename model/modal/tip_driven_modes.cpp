#include "model/modal/tip_driven_modes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace nibrig::model::modal {

std::vector<double> tip_driven_frequencies_hz(const ModalModel& modal, std::size_t count,
                                              double relative) {
  double largest = 0;
  for (double b : modal.input) largest = std::max(largest, std::abs(b));
  std::vector<double> f;
  for (std::size_t i = 0; i < modal.size() && f.size() < count; ++i)
    if (std::abs(modal.input[i]) > relative * largest)
      f.push_back(modal.omega[i] / (2 * std::numbers::pi));
  return f;
}

}  // namespace nibrig::model::modal
