#include "model/design/design_grid_file.hpp"

#include <spdlog/spdlog.h>

#include <nlohmann/json.hpp>
#include <system_error>

#include "model/io/atomic_file.hpp"
#include "model/io/finite_output.hpp"
#include "model/io/format_error.hpp"
#include "model/io/json_fields.hpp"
#include "model/io/user_cache.hpp"
#include "model/mechanics/lab_materials.hpp"

namespace nibrig::model::design {

namespace {

namespace jf = io::json_fields;
using nlohmann::json;

constexpr const char* kFormat = "nibrig-design-grid";

std::vector<double> numbers(const json& object, const std::string& key,
                            const std::filesystem::path& file, const std::string& parent) {
  return jf::as_number_array(jf::member(object, key, file, parent), file,
                             jf::member_path(parent, key));
}

}  // namespace

std::string design_grid_cache_key(const PredictionInputs& inputs, const GridAxes& axes) {
  io::CacheKey key;
  key.add(std::string_view(kFormat)).add(static_cast<std::int64_t>(kDesignGridFormatVersion));
  key.add_file(inputs.design_template_file).add_file(inputs.materials_file);
  mechanics::add_lab_materials(key);
  key.add(axes.material_a).add(axes.material_b);
  key.add(static_cast<std::int64_t>(axes.fractions.size()));
  for (double f : axes.fractions) key.add(f);
  key.add(static_cast<std::int64_t>(axes.tips_m.size()));
  for (double t : axes.tips_m) key.add(t);
  key.add(solved_mesh_size(inputs.setup))
      .add(static_cast<std::int64_t>(solved_modes(inputs.setup)));
  key.add(static_cast<std::int64_t>(inputs.model.frequencies_hz.size()));
  for (double f : inputs.model.frequencies_hz) key.add(f);
  return key.hex();
}

GridAxes default_grid_axes(const PredictionInputs& inputs, const std::string& material_a,
                           const std::string& material_b) {
  const auto& tips = inputs.model.tip_log_gain;
  return even_axes(material_a, material_b, kDefaultFractionPoints, tips.begin()->first,
                   tips.rbegin()->first, kDefaultTipPoints);
}

std::filesystem::path design_grid_cache_file(const std::string& key) {
  return io::user_cache_dir() / ("design-grid-" + key + ".json");
}

void write_design_grid(const std::filesystem::path& file, const DesignResponseGrid& grid,
                       const std::string& key) {
  json out;
  out["format"] = kFormat;
  out["version"] = kDesignGridFormatVersion;
  out["key"] = key;
  out["materials"] = {grid.axes.material_a, grid.axes.material_b};
  out["fractions"] = grid.axes.fractions;
  out["tip_diameters_m"] = grid.axes.tips_m;
  out["frequencies_hz"] = grid.frequencies_hz;
  out["mesh_size_m"] = grid.mesh_size_m;
  out["modes"] = grid.modes;
  out["nodes"] = json::array();
  for (const auto& node : grid.nodes)
    out["nodes"].push_back({{"design", node.design_name},
                            {"response_magnitude", node.response_magnitude},
                            {"omega_rad_s", node.modal.omega},
                            {"zeta", node.modal.zeta},
                            {"input", node.modal.input},
                            {"output", node.modal.output}});
  std::error_code error;
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), error);
  if (error)
    throw std::runtime_error(file.parent_path().string() + ": cannot create the cache folder (" +
                             error.message() + ")");
  // dump() writes each double with the digits that read back to the same double.
  io::write_file_atomically(file, io::json_text(out, file, -1));
}

DesignResponseGrid read_design_grid(const std::filesystem::path& file,
                                    const std::string& expected_key) {
  const json root = jf::parse_file(file);
  jf::as_object(root, file, "");
  jf::check_format_and_version(root, file, kFormat, kDesignGridFormatVersion);
  if (jf::as_integer(jf::member(root, "version", file, ""), file, "version", 0, 1LL << 40) !=
      kDesignGridFormatVersion)
    throw io::FormatError(file, jf::place("version"),
                          "expected version " + std::to_string(kDesignGridFormatVersion) +
                              " (an older grid is recomputed, not read)");
  const std::string key = jf::string_member(root, "key", file, "");
  if (!expected_key.empty() && key != expected_key)
    throw io::FormatError(
        file, jf::place("key"),
        "expected '" + expected_key + "' (the grid of these inputs), found '" + key + "'");
  DesignResponseGrid grid;
  const json& materials = jf::as_array(jf::member(root, "materials", file, ""), file, "materials");
  if (materials.size() != 2)
    throw io::FormatError(file, jf::place("materials"), "expected the two materials of the mix");
  grid.axes.material_a = jf::as_string(materials[0], file, jf::element_path("materials", 0));
  grid.axes.material_b = jf::as_string(materials[1], file, jf::element_path("materials", 1));
  grid.axes.fractions = numbers(root, "fractions", file, "");
  grid.axes.tips_m = numbers(root, "tip_diameters_m", file, "");
  grid.frequencies_hz = numbers(root, "frequencies_hz", file, "");
  grid.mesh_size_m = jf::number_member(root, "mesh_size_m", file, "");
  grid.modes = static_cast<int>(
      jf::as_integer(jf::member(root, "modes", file, ""), file, "modes", 1, 100000));
  const json& nodes = jf::as_array(jf::member(root, "nodes", file, ""), file, "nodes");
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    const std::string at = jf::element_path("nodes", n);
    jf::as_object(nodes[n], file, at);
    SimulatedResponse node;
    node.design_name = jf::string_member(nodes[n], "design", file, at);
    node.response_magnitude = numbers(nodes[n], "response_magnitude", file, at);
    node.modal.omega = numbers(nodes[n], "omega_rad_s", file, at);
    node.modal.zeta = numbers(nodes[n], "zeta", file, at);
    node.modal.input = numbers(nodes[n], "input", file, at);
    node.modal.output = numbers(nodes[n], "output", file, at);
    grid.nodes.push_back(std::move(node));
  }
  try {
    validate(grid, "the grid");
  } catch (const std::invalid_argument& e) {
    throw io::FormatError(file, "", e.what());
  }
  grid.mode_jumps = count_mode_jumps(grid);
  return grid;
}

std::optional<DesignResponseGrid> load_cached_design_grid(const PredictionInputs& inputs,
                                                          const GridAxes& axes) {
  const std::string key = design_grid_cache_key(inputs, axes);
  const std::filesystem::path file = design_grid_cache_file(key);
  std::error_code error;
  for (const auto& candidate : {file, io::shipped_twin(file)}) {
    if (candidate.empty() || !std::filesystem::exists(candidate, error)) continue;
    try {
      DesignResponseGrid grid = read_design_grid(candidate, key);
      // The key holds the axes' exact bits; a file that says otherwise was not written for them.
      if (grid.axes.material_a != axes.material_a || grid.axes.material_b != axes.material_b ||
          grid.axes.fractions != axes.fractions || grid.axes.tips_m != axes.tips_m ||
          grid.frequencies_hz != inputs.model.frequencies_hz)
        throw io::FormatError(candidate, "",
                              "its axes or frequencies are not those its key stands for");
      return grid;
    } catch (const std::exception& e) {
      spdlog::warn("the cached design grid cannot be used, it is recomputed: {}", e.what());
      if (candidate == file)
        std::filesystem::remove(file, error);  // the shipped layer is read-only
    }
  }
  return std::nullopt;
}

namespace {

// Computes the grid over `axes` (reusing `known`'s nodes) and caches it.
DesignResponseGrid compute_and_cache_grid(const PredictionInputs& inputs, const GridAxes& axes,
                                          const numeric::Progress& progress, std::stop_token stop,
                                          unsigned threads, const DesignResponseGrid* known) {
  DesignResponseGrid grid =
      compute_design_response_grid(inputs.setup, axes, progress, stop, threads, known);
  const std::string key = design_grid_cache_key(inputs, axes);
  try {
    write_design_grid(design_grid_cache_file(key), grid, key);
  } catch (const std::exception& e) {
    spdlog::warn(
        "the design grid was computed but cannot be cached (it is recomputed next time): {}",
        e.what());
  }
  return grid;
}

std::size_t grid_node_count(const GridAxes& axes) {
  return axes.fractions.size() * axes.tips_m.size();
}

}  // namespace

DesignResponseGrid cached_design_response_grid(
    const PredictionInputs& inputs, const GridAxes& axes, const numeric::StepProgress& progress,
    std::stop_token stop, unsigned threads,
    const std::function<void(const DesignResponseGrid&)>& on_coarse) {
  if (auto cached = load_cached_design_grid(inputs, axes)) return std::move(*cached);
  const GridAxes coarse_grid_axes = coarse_axes(axes);
  if (!on_coarse || grid_node_count(coarse_grid_axes) == grid_node_count(axes))
    return compute_and_cache_grid(
        inputs, axes, numeric::step_progress(progress, kFineGridStep, grid_node_count(axes)), stop,
        threads, nullptr);
  std::optional<DesignResponseGrid> coarse = load_cached_design_grid(inputs, coarse_grid_axes);
  if (!coarse) {
    coarse = compute_and_cache_grid(
        inputs, coarse_grid_axes,
        numeric::step_progress(progress, kCoarseGridStep, grid_node_count(coarse_grid_axes)), stop,
        threads, nullptr);
  }
  on_coarse(*coarse);
  // Every coarse node is a fine node solved with the same inputs (coarse_axes, the same key's
  // inputs): exactly these remain to solve.
  return compute_and_cache_grid(
      inputs, axes,
      numeric::step_progress(progress, kFineGridStep,
                             grid_node_count(axes) - grid_node_count(coarse_grid_axes)),
      stop, threads, &*coarse);
}

DesignResponseGrid cached_design_response_grid(
    const PredictionInputs& inputs, const GridAxes& axes, const numeric::Progress& progress,
    std::stop_token stop, unsigned threads,
    const std::function<void(const DesignResponseGrid&)>& on_coarse) {
  numeric::StepProgress steps;
  if (progress)
    steps = [progress](const std::string&, std::size_t done, std::size_t total) {
      if (done > 0) progress(done, total);  // the steps' announcements are not units
    };
  return cached_design_response_grid(inputs, axes, steps, stop, threads, on_coarse);
}

}  // namespace nibrig::model::design
