#include "ui/figures/predicted_text.hpp"

#include <fmt/format.h>

#include <cmath>

#include "model/forcing/descriptor_error.hpp"
#include "model/space/catalog_descriptors.hpp"

namespace nibrig::ui::figures {

std::string describe_descriptors(const model::design::PredictedTool& tool) {
  std::string mu = fmt::format("mu {:.3f}", tool.mu);
  std::string vibration =
      fmt::format("weighted mean vibration {:.4g}", tool.vibration.weighted_mean);
  if (!tool.descriptor_errors.empty()) {
    const auto names = model::space::paper_descriptor_names(2);  // μ, log10 weighted mean
    const Eigen::MatrixXd c = tool.descriptor_errors.block(names);
    if (c(0, 0) > 0) mu += fmt::format(" ± {:.4f}", std::sqrt(c(0, 0)));
    vibration += fmt::format(" ± {:.1f} %", model::forcing::percent_off(std::sqrt(c(1, 1))));
  }
  return mu + ", " + vibration;
}

}  // namespace nibrig::ui::figures
