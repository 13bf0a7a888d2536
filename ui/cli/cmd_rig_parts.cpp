// `nibrig rig parts -o DIR`: the rig's printed parts as files a printer takes. The work is
// rig/printed_parts_files.hpp's (write_rig_parts); this file holds the option and the printing.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "rig/printed_parts_files.hpp"
#include "ui/cli/commands.hpp"
#include "ui/cli/logging.hpp"
#include "ui/cli/output.hpp"

namespace nibrig::ui::cli {
namespace {

void write_parts(const std::filesystem::path& folder) {
  const rig::RigPartDimensions dimensions;
  const auto written = rig::write_rig_parts(folder, dimensions);
  const auto& recipe = written.recipe_json;
  for (std::size_t i = 0; i < written.parts.size(); ++i) {
    const auto& p = recipe["parts"][i];
    const auto& lo = p["bed_box_mm"]["min"];
    const auto& hi = p["bed_box_mm"]["max"];
    std::printf("%s: %.0f mm3 of %s, %.1f x %.1f x %.1f mm on the bed, %d perimeters, %d %% %s\n",
                p["title"].get<std::string>().c_str(), p["volume_mm3"].get<double>(),
                p["material"].get<std::string>().c_str(), hi[0].get<double>() - lo[0].get<double>(),
                hi[1].get<double>() - lo[1].get<double>(),
                hi[2].get<double>() - lo[2].get<double>(), p["settings"]["perimeters"].get<int>(),
                p["settings"]["fill_percent"].get<int>(),
                p["settings"]["fill_pattern"].get<std::string>().c_str());
    const auto& files = written.parts[i];
    for (const auto& file : {files.three_mf, files.stl, files.ini, files.drawing}) say_wrote(file);
  }
  std::printf("pivot %.1f mm above the base: the post's 20 x 20 extrusion %.1f mm long\n",
              rig::pivot_height(dimensions) * 1e3, rig::post_extrusion_length(dimensions) * 1e3);
  say_wrote(written.recipe);
}

}  // namespace

void add_rig_parts_command(CLI::App* rig, std::shared_ptr<const GlobalOptions> global) {
  auto folder = std::make_shared<std::filesystem::path>();
  auto* cmd = rig->add_subcommand(
      "parts", "Write the rig's printed parts: 3MF, STL, PrusaSlicer settings and a drawing each");
  cmd->footer(
      "Five parts (rig/PARTS.md): arm_post, bearing_bridge, cell_bracket, tool_holder,\n"
      "accelerometer_mount. Each as <name>.3mf (PETG, placed on a 200 x 200 mm bed) and "
      "<name>.stl,\n"
      "<name>.ini (slice with: prusa-slicer --load <name>.ini <name>.3mf) and <name>.svg, its\n"
      "dimensioned drawing; rig_parts.json sums them up. Other files in DIR are left alone.");
  cmd->add_option("-o,--output", *folder, "Folder to write the parts into (made when new)")
      ->required();
  cmd->callback([folder, global] {
    configure_logging(global->verbosity);
    write_parts(*folder);
  });
}

}  // namespace nibrig::ui::cli
