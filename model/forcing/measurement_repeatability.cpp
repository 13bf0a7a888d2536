#include "model/forcing/measurement_repeatability.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "model/forcing/leave_one_out.hpp"

namespace nibrig::model::forcing {

Repeatability nail_pair_repeatability(const io::Catalog& catalog) {
  const std::string first_suffix = "_nail1", second_suffix = "_nail2";
  Repeatability out;
  double sum = 0.0;
  for (const auto& a : catalog.pairings) {
    if (!a.vibration || a.tool.size() <= first_suffix.size() ||
        a.tool.compare(a.tool.size() - first_suffix.size(), first_suffix.size(), first_suffix) != 0)
      continue;
    const std::string second =
        a.tool.substr(0, a.tool.size() - first_suffix.size()) + second_suffix;
    for (const auto& b : catalog.pairings) {
      if (b.tool != second || b.surface != a.surface || !b.vibration) continue;
      const double db = log_spectrum_error(a.vibration->spectrum, b.vibration->spectrum).rms_db;
      sum += db;
      out.pairs.push_back(fmt::format("{} / {} on {}: {:.2f} dB", a.tool, b.tool, a.surface, db));
    }
  }
  if (out.pairs.empty())
    throw std::invalid_argument(
        "the catalog holds no print recorded twice (a '<tool>_nail1' and '<tool>_nail2' pair on "
        "one surface, both with spectra), so the measurement's repeatability cannot be computed");
  out.rms_db = sum / static_cast<double>(out.pairs.size());
  return out;
}

}  // namespace nibrig::model::forcing
