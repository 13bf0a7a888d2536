// The design-response grid kept between runs (model/io/FORMATS.md, "Design-response grid"):
// computed once, then read back instead of solved again. The file's name is the
// cache key of every input the grid depends on, so a changed input is a different file and a
// stale grid is never read; the file also holds its key, so a file copied or renamed by hand is
// refused rather than trusted.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <stop_token>
#include <string>

#include "model/design/design_response_grid.hpp"
#include "model/design/prediction_inputs.hpp"

namespace nibrig::model::design {

// Bumped whenever the grid's content or its computation changes (the file's layout, mixed_design's
// insert, the FEM), so that grids of an older nibrig are recomputed rather than read.
inline constexpr long long kDesignGridFormatVersion = 1;

// The key of a grid over `axes` for these inputs: the content of the template design and material
// table files, the two materials and both axes, the mesh size and mode count solved with, the
// forcing model's frequency grid, and the format version. Throws std::runtime_error naming a file
// that cannot be read.
std::string design_grid_cache_key(const PredictionInputs& inputs, const GridAxes& axes);

// The default grid of two materials for these inputs: kDefaultFractionPoints mixes ×
// kDefaultTipPoints tips over the forcing model's fitted tips (what `design --grid`, Python's
// search(grid=True) and the shipped defaults solve).
GridAxes default_grid_axes(const PredictionInputs& inputs, const std::string& material_a,
                           const std::string& material_b);

// user_cache_dir() / "design-grid-<key>.json".
std::filesystem::path design_grid_cache_file(const std::string& key);

// Writes atomically (io::write_file_atomically), creating the folder. Throws std::runtime_error
// naming the file when it cannot be written.
void write_design_grid(const std::filesystem::path& file, const DesignResponseGrid& grid,
                       const std::string& key);

// Throws io::FormatError naming the file and the field for anything malformed or inconsistent
// (a truncated file, a node of the wrong length, a key other than `expected_key` when one is given).
DesignResponseGrid read_design_grid(const std::filesystem::path& file,
                                    const std::string& expected_key = "");

// The cached grid for these inputs, or nullopt when there is none yet. A file that cannot be read
// (corrupt, truncated, another key) is reported in the log with its error, removed, and nullopt
// returned: the caller recomputes it, nothing crashes.
std::optional<DesignResponseGrid> load_cached_design_grid(const PredictionInputs& inputs,
                                                          const GridAxes& axes);

// The steps cached_design_response_grid announces (numeric::StepProgress): the coarse grid's
// nodes, then the fine grid's (without on_coarse the one step is the fine grid's).
inline constexpr const char* kCoarseGridStep = "coarse grid";
inline constexpr const char* kFineGridStep = "fine grid";

// The cached grid, else computed (compute_design_response_grid with progress, stop and threads)
// and written to the cache. A stop throws numeric::Cancelled (nothing of the grid stopped is
// written then). A cache that cannot be written is a warning in the log, not an error: the grid computed is
// returned all the same.
//
// With on_coarse, and the grid not cached, a usable grid comes first: the coarse_axes grid, taken
// from the cache or solved and cached (under its own key, as any grid), is passed to on_coarse;
// the grid asked for is then solved reusing the coarse nodes (only the rest are solved), cached and
// returned. on_coarse is not called when the grid is cached, nor for a grid of 2 × 2 nodes (its own
// coarse grid). A stop in either phase throws numeric::Cancelled; a coarse grid completed stays
// cached.
//
// Progress: each step solved is announced with done = 0 (kCoarseGridStep, then kFineGridStep) and
// counted in the nodes it solves (5 × 7: 12, then 23); a step with nothing to solve (a cached
// coarse grid) is not announced. The numeric::Progress form is called with those same counts, the
// coarse grid's before on_coarse and the fine grid's after it.
DesignResponseGrid cached_design_response_grid(
    const PredictionInputs& inputs, const GridAxes& axes, const numeric::StepProgress& progress,
    std::stop_token stop = {}, unsigned threads = 0,
    const std::function<void(const DesignResponseGrid&)>& on_coarse = {});
DesignResponseGrid cached_design_response_grid(
    const PredictionInputs& inputs, const GridAxes& axes, const numeric::Progress& progress = {},
    std::stop_token stop = {}, unsigned threads = 0,
    const std::function<void(const DesignResponseGrid&)>& on_coarse = {});

}  // namespace nibrig::model::design
