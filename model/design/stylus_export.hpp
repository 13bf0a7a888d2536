// A design point made printable (the paper's "fabrication"): the stylus its prediction simulated,
// region by region exactly as the FEM meshed it (mechanics/region_surface.hpp), each region with
// what the printer loads for it — a material of the table, or for a mixed tip the fractions a
// PolyJet printer's digital-material mixing takes — written as one 3MF part (lib3mf) and an STL per
// region.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "model/design/design_point.hpp"
#include "model/design/predicted_tool.hpp"
#include "model/design/single_material_substitute.hpp"
#include "model/forcing/forcing_inputs.hpp"
#include "model/io/printer_profile.hpp"
#include "model/io/surface_mesh.hpp"

namespace nibrig::model::design {

struct StylusRegion {
  io::SurfaceMesh surface;          // metres, the stylus along +x from its back end
  std::string material;             // the material table's name (a mix: its rule-of-mixtures entry)
  std::vector<MaterialShare> mix;   // what the printer deposits: catalog materials and fractions
};

struct StylusPrint {
  DesignPoint point;
  std::string design_name;
  mechanics::Design design;  // what the FEM solved: shape, regions' materials, mesh size, modes
  mechanics::MaterialTable materials;
  std::vector<StylusRegion> regions;  // in the mesh's region order ("body", then "tip")
  // For a printer that cannot mix: filled by a face that has a space to place them in (design
  // --export); written into the recipe.
  std::vector<Substitute> substitutes;
  // The printer it is made for (set by the face from --printer, after check_printable): its
  // orientation and bed place the part, its slicer settings go into the 3MF and the .ini beside
  // it, and the recipe and sheet state them. None: lying on PrusaSlicer's default bed, no settings.
  std::optional<io::PrinterProfile> printer;
};

// The stylus of `point` as a prediction with `setup` meshes it (its template, materials, mesh size
// and modes). A single material of the table that the catalog never printed (a lab's PLA, a resin)
// makes the whole template stylus of that material: printable, though the forcing model cannot
// predict it until the material is calibrated. Throws std::invalid_argument naming the point: a material the printed tools do not
// have (outside the material table), or a tip the stylus's geometry cannot take (the geometry's
// own message: the tip wider than the body, or not a positive length).
StylusPrint stylus_print(const PredictionSetup& setup, const DesignPoint& point);

// The same with the template and materials `inputs` names (the bundled ones by default), at its
// mesh size and modes: the stylus `nibrig predict` with those options solves. Throws what reading
// them throws, naming the file.
StylusPrint stylus_print(const forcing::ForcingInputOptions& inputs, const DesignPoint& point);

// The name a printer operator reads for a region's material: "VeroClear-Piovarci2018", or a mix
// as "DM85 62 % + vero 38 % (digital material)".
std::string printer_material(const StylusRegion& region);

struct StylusFiles {
  std::filesystem::path three_mf;
  std::vector<std::filesystem::path> stls;  // <stem>-<region>.stl beside it, in region order
  std::filesystem::path recipe;             // <stem>.json beside it
  std::filesystem::path slicer_config;      // <stem>.ini beside it for a PrusaSlicer printer, else empty
};

// The recipe, for people and scripts (FORMATS.md "Stylus for a printer"): kind "stylus_recipe",
// design, design_name, mesh_size_mm, regions [{name, material, printer_material, mix [{material,
// fraction}], triangles, volume_mm3}], substitutes [{design, cost, cost_sd, to_target and
// to_target_sd (when searched for a target), outside_constraints (when it breaks one)}], files
// {three_mf, stls, slicer_config}; each region's material_basis; with a printer, `printer` (its
// name, process, orientation and why, supports, post-processing, settings with their sources, the
// slicer's settings and the command that slices the 3MF with them).
nlohmann::json stylus_recipe_json(const StylusPrint& print, const StylusFiles& files);

// Refuses (std::runtime_error naming it) a folder the files cannot go into: one that exists and
// cannot be written, or a new one whose nearest existing parent cannot. Nothing is made: a long
// search checks its --export folder with this before it starts.
void check_stylus_folder(const std::filesystem::path& folder);

// The same for the files themselves, before the work that makes them: the folder, then the 3MF and
// the recipe and the .ini, each refused when it would replace a file the running job read
// (io/job_files.hpp), and the recipe and .ini when they are links. Throws std::runtime_error naming the file.
void check_stylus_outputs(const std::filesystem::path& three_mf);

// Where write_stylus_files puts everything for a 3MF named `three_mf`.
StylusFiles stylus_files(const std::filesystem::path& three_mf, const StylusPrint& print);

// The 3MF (one part, an object per region with its material, placed lying along x on the
// PrusaSlicer command line's default 200 × 200 mm bed, or as print.printer orients it in the middle
// of its bed, with its slicer settings inside), the STLs, the .ini and the recipe. A printer that
// cannot make the print is refused first (check_printable, PrintRefused). The folder is checked first
// (check_stylus_folder) and made when new; each file is then written atomically. Throws std::runtime_error naming the file.
StylusFiles write_stylus_files(const std::filesystem::path& three_mf, const StylusPrint& print);

}  // namespace nibrig::model::design
