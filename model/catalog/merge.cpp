#include "model/catalog/merge.hpp"

#include <map>
#include <stdexcept>
#include <utility>

namespace nibrig::model::catalog {

namespace {

bool same_tool(const io::ToolEntry& a, const io::ToolEntry& b) {
  return a.name == b.name && a.kind == b.kind && a.material == b.material && a.tip_diameter_m == b.tip_diameter_m;
}

}  // namespace

io::Catalog merge_catalogs(const std::vector<NamedCatalog>& catalogs) {
  io::Catalog out;
  std::map<std::string, std::pair<io::ToolEntry, std::string>> tools;        // id → entry, from
  std::map<std::string, std::pair<io::SurfaceEntry, std::string>> surfaces;  // id → entry, from
  std::map<std::pair<std::string, std::string>, std::string> pairings;       // (tool, surface) → from
  for (const auto& [name, catalog] : catalogs) {
    if (!catalog.citation.empty() && out.citation.find(catalog.citation) == std::string::npos)
      out.citation += (out.citation.empty() ? "" : "; ") + catalog.citation;
    for (const auto& tool : catalog.tools) {
      const auto [it, added] = tools.try_emplace(tool.id, tool, name);
      if (added)
        out.tools.push_back(tool);
      else if (!same_tool(it->second.first, tool))
        throw std::invalid_argument("tool '" + tool.id + "' is described differently in " + it->second.second +
                                    " and " + name + ": give one of them another id");
    }
    for (const auto& surface : catalog.surfaces) {
      const auto [it, added] = surfaces.try_emplace(surface.id, surface, name);
      if (added)
        out.surfaces.push_back(surface);
      else if (it->second.first.name != surface.name)
        throw std::invalid_argument("surface '" + surface.id + "' is '" + it->second.first.name + "' in " +
                                    it->second.second + " and '" + surface.name + "' in " + name);
    }
    for (const auto& pairing : catalog.pairings) {
      const auto [it, added] = pairings.try_emplace({pairing.tool, pairing.surface}, name);
      if (!added)
        throw std::invalid_argument(pairing.tool + " on " + pairing.surface + " is measured in both " + it->second +
                                    " and " + name + ": keep one of the two measurements");
      out.pairings.push_back(pairing);
    }
    for (const auto& note : catalog.notes) out.notes.push_back(name + ": " + note);
  }
  return out;
}

}  // namespace nibrig::model::catalog
