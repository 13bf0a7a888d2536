#include "model/forcing/catalog_exemplars.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <map>
#include <stdexcept>
#include <tuple>

#include "model/forcing/printed_tool_design.hpp"
#include "model/mechanics/design_model.hpp"
#include "model/modal/frequency_response.hpp"

namespace nibrig::model::forcing {

ExemplarSelection select_printed_exemplars(const io::Catalog& catalog,
                                           const mechanics::MaterialTable* materials) {
  const auto has_design = [&](const std::string& material) {
    return materials ? has_printed_design(material, *materials) : has_printed_design(material, {});
  };
  std::map<std::string, const io::ToolEntry*> tools;
  for (const auto& t : catalog.tools) tools[t.id] = &t;
  ExemplarSelection selection;
  for (const auto& p : catalog.pairings) {
    const auto found = tools.find(p.tool);
    if (found == tools.end()) continue;  // read_catalog refuses such a pairing
    const io::ToolEntry& tool = *found->second;
    const std::string name = p.tool + " on " + p.surface;
    if (tool.kind != "printed") {
      ++selection.other_kinds;
      continue;
    }
    if (tool.id.find("_nail") != std::string::npos) {
      selection.excluded.push_back(name +
                                   ": a variant of a printed tool (after a nail test), no "
                                   "design of its own");
    } else if (!tool.tip_diameter_m) {
      selection.excluded.push_back(name + ": no tip diameter in the catalog, so no design");
    } else if (!has_design(tool.material)) {
      selection.excluded.push_back(name + ": material '" + tool.material + "' has no design");
    } else if (!p.vibration) {
      selection.excluded.push_back(name + ": no vibration spectrum in the catalog");
    } else {
      selection.exemplars.push_back({p.tool,
                                     p.surface,
                                     tool.material,
                                     *tool.tip_diameter_m,
                                     p.vibration->spectrum,
                                     {},
                                     {},
                                     false});
    }
  }
  return selection;
}

bool is_paper_tool(const ForcingExemplar& e) {
  const bool material = e.material == "vero" || e.material == "DM95" || e.material == "DM85";
  const bool surface = e.surface == "office" || e.surface == "note" || e.surface == "stone";
  const double d = e.tip_diameter_m * 1e3;
  const bool tip = std::abs(d - 1) < 1e-3 || std::abs(d - 2) < 1e-3 || std::abs(d - 4) < 1e-3;
  return material && surface && tip;
}

std::vector<std::string> missing_paper_tools(const std::vector<ForcingExemplar>& exemplars) {
  std::vector<std::string> missing;
  for (const std::string material : {"vero", "DM95", "DM85"})
    for (const int tip : {1, 2, 4})
      for (const std::string surface : {"office", "note", "stone"}) {
        const bool present = std::any_of(exemplars.begin(), exemplars.end(), [&](const auto& e) {
          return e.material == material && e.surface == surface &&
                 std::abs(e.tip_diameter_m * 1e3 - tip) < 1e-3;
        });
        // Catalog ids of the printed tools: vero1, DM852, ...
        if (!present) missing.push_back(material + std::to_string(tip) + " on " + surface);
      }
  return missing;
}

std::vector<DesignResponse> attach_responses(
    std::vector<ForcingExemplar>& exemplars, const mechanics::Design& template_design,
    const mechanics::MaterialTable& materials, const ResponseOptions& options,
    const std::function<void(const DesignResponse&, std::size_t, std::size_t)>& progress) {
  // Key of a design: tip material, insert length, whole tool, tip diameter in µm (tips come from a
  // file in mm).
  using Key = std::tuple<std::string, double, bool, long long>;
  std::map<Key, std::vector<std::size_t>> users;
  std::vector<Key> order;
  for (std::size_t e = 0; e < exemplars.size(); ++e) {
    const PrintedTip tip = printed_tip_of(exemplars[e].material, materials);
    const Key key{materials.find(tip.material).name, tip.insert_length, tip.whole_tool,
                  std::llround(exemplars[e].tip_diameter_m * 1e6)};
    if (!users.count(key)) order.push_back(key);
    users[key].push_back(e);
  }

  std::vector<DesignResponse> computed;
  for (const Key& key : order) {
    const auto& members = users.at(key);
    const ForcingExemplar& first = exemplars[members.front()];
    const auto start = std::chrono::steady_clock::now();
    mechanics::Design design =
        printed_tool_design(printed_tip_of(first.material, materials), first.tip_diameter_m,
                            template_design, materials);
    if (options.mesh_size > 0) design.mesh_size = options.mesh_size;
    if (options.modes > 0) design.modes = options.modes;
    const mechanics::DesignModel model = mechanics::build_design_model(design, materials);

    DesignResponse response;
    response.design = design.name;
    response.modes = model.modal.size();
    response.first_mode_hz = model.modal.omega.front() / (2 * M_PI);
    std::map<std::vector<double>, std::vector<double>> by_grid;  // one H per frequency grid
    for (std::size_t e : members) {
      auto& exemplar = exemplars[e];
      auto& magnitude = by_grid[exemplar.measured.frequencies_hz];
      if (magnitude.empty())
        for (const auto& h :
             modal::frequency_response(model.modal, exemplar.measured.frequencies_hz))
          magnitude.push_back(std::abs(h));
      exemplar.response_magnitude = magnitude;
      const std::string user = exemplar.material + " " + tip_label(exemplar.tip_diameter_m);
      if (std::find(response.used_by.begin(), response.used_by.end(), user) ==
          response.used_by.end())
        response.used_by.push_back(user);
    }
    response.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (progress) progress(response, computed.size() + 1, order.size());
    computed.push_back(std::move(response));
  }
  return computed;
}

}  // namespace nibrig::model::forcing
