// Colour tables for report figures: the perceptually uniform viridis map for values and a
// colour-blind-safe categorical palette for curves and groups.
#pragma once

#include <array>
#include <cstddef>

namespace nibrig::ui::report {

struct Rgb {
  int r, g, b;  // 0-255
};

// The 256 entries of viridis (van der Walt and Smith, matplotlib's default map; CC0), low to high.
const std::array<Rgb, 256>& viridis();

// Viridis at t in [0, 1] (clamped), nearest entry.
Rgb viridis_at(double t);

// Ten distinct hues that stay distinguishable with the common colour-vision deficiencies.
const std::array<Rgb, 10>& categorical_palette();

}  // namespace nibrig::ui::report
