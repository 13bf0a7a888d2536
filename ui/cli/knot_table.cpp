#include "ui/cli/knot_table.hpp"

#include <fmt/format.h>

#include "model/forcing/forcing_model.hpp"

namespace nibrig::ui::cli {

std::string knot_table_header(const std::string& label, const std::vector<double>& knots_hz,
                              int label_width) {
  std::string out = fmt::format("{:<{}}", label, label_width);
  for (double f : knots_hz) out += fmt::format("{:>7g}", f);
  return out + "\n";
}

std::string knot_table_rows(const std::string& label, const std::vector<double>& log_gains,
                            const std::vector<double>& standard_errors, int label_width) {
  const auto row = [&](const std::string& name, const std::vector<double>& values) {
    std::string out = fmt::format("{:<{}}", name, label_width);
    for (double v : values) out += fmt::format("{:>7.2f}", model::forcing::log_gain_to_db(v));
    return out + "\n";
  };
  return row(label, log_gains) +
         (standard_errors.empty() ? std::string() : row("  ± (SE)", standard_errors));
}

}  // namespace nibrig::ui::cli
