// A lab's own materials, fitted to its prints (`nibrig material calibrate`): one file per name in
// the user store, beside (never over) the bundled assets/materials.json. Each file is a material
// table ("nibrig-materials") of one material plus a `calibration` object saying what it was fitted
// from; read_material_table finds these after the table's own materials.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "model/io/user_cache.hpp"
#include "model/mechanics/material_table.hpp"

namespace nibrig::model::mechanics {

// $NIBRIG_MATERIALS, else $XDG_DATA_HOME/nibrig/materials, else ~/.local/share/nibrig/materials.
std::filesystem::path lab_materials_folder();

// Where a lab material of `name` is kept: <folder>/<name>.json (made safe for a file name).
std::filesystem::path lab_material_file(const std::string& name);

// One lab material's file in `folder`, its printed_as from its calibration. Throws io::FormatError
// naming the file for one that is not a table of exactly one material, or whose material's name is
// not the one its file name says.
Material read_lab_material_file(const std::filesystem::path& file,
                                const std::filesystem::path& folder);

// Every *.json in the folder (none when it does not exist), by file name, as
// read_lab_material_file reads each (and throws).
std::vector<Material> read_lab_materials(const std::filesystem::path& folder);

// `table` with the lab's materials after its own. A lab material named as one of the table's is
// left out: the table wins, because the table is what the design was made with (a bundled name is
// refused at saving, so only a table given with --materials can hold such a name). A lab file that
// cannot be read is left out too, so that one broken file stops no command that does not need it:
// a warning names it once per process, and a material looked for and not found names it in
// find()'s error with why it was skipped.
MaterialTable with_lab_materials(const MaterialTable& table,
                                 const std::filesystem::path& folder = lab_materials_folder());

// Adds every lab material file's name and content to `key`: a cached result computed from the
// material table (io/user_cache.hpp) is stale once the lab recalibrates, adds or removes one.
void add_lab_materials(io::CacheKey& key,
                       const std::filesystem::path& folder = lab_materials_folder());

// Refuses (std::invalid_argument naming the name and the file) a name that `bundled` holds, and a
// name the lab already has unless `replace`: what save_lab_material checks, for a face to ask
// before a long fit.
void check_lab_material_name(const std::string& name, const MaterialTable& bundled, bool replace);

// Writes `material` (basis "fitted") with `calibration` into the lab's folder, atomically, and
// returns the file, after check_lab_material_name.
std::filesystem::path save_lab_material(const Material& material, const nlohmann::json& calibration,
                                        const MaterialTable& bundled, bool replace);

}  // namespace nibrig::model::mechanics
