// Figures of perceptual spaces: the space with its bootstrap regions and tools placed from
// descriptors (Fig. 9, 15), and the cross-validated error of the dimension × λ scan (Fig. 8).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "model/space/descriptor_map.hpp"
#include "model/space/dimension_scan.hpp"
#include "model/space/space_file.hpp"
#include "ui/figures/space_scatter.hpp"

namespace nibrig::ui::cli {

using figures::PlacedTool;

// figures::space_scatter on a page of its own.
void write_space_plot(const model::space::SpaceFile& space, const std::vector<PlacedTool>& placed,
                      const std::string& title, const std::filesystem::path& png);

// Error against λ, one curve per dimension (against dimensions when only one λ was swept).
void write_dimension_scan_plot(const std::vector<model::space::DimensionScanPoint>& points,
                               const std::string& title, const std::filesystem::path& png);

}  // namespace nibrig::ui::cli
