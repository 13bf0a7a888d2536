#include "model/catalog/tool_names.hpp"

#include <map>
#include <regex>

namespace nibrig::model::catalog {

namespace {

struct KnownTool {
  const char* name;
  const char* kind;
};

const std::map<std::string, KnownTool>& known_tools() {
  static const std::map<std::string, KnownTool> tools = {
      {"pen", {"ballpoint pen", "real"}},
      {"fine", {"fine-liner", "real"}},
      {"p2h", {"2H pencil", "real"}},
      {"p8b", {"8B pencil", "real"}},
      {"charc", {"charcoal", "real"}},
      {"cryon", {"crayon", "real"}},
      {"stab", {"STABILO pencil (a further real tool)", "real"}},
      {"apencil", {"Apple Pencil", "commercial"}},
      {"m2h", {"Surface Pen nib 2H", "commercial"}},
      {"mhb", {"Surface Pen nib HB", "commercial"}},
      {"mb", {"Surface Pen nib B", "commercial"}},
      {"wnylon", {"Wacom nylon nib", "commercial"}},
      {"wfelt", {"Wacom felt nib", "commercial"}},
      {"wrubber", {"Wacom rubber nib", "commercial"}},
  };
  return tools;
}

std::string material_name(const std::string& material) {
  if (material == "vero") return "VeroClear";
  if (material == "DM85") return "DM85 (Shore A 85)";
  if (material == "DM95") return "DM95 (Shore A 95)";
  if (material == "teflon") return "teflon-taped";
  return material;
}

}  // namespace

io::ToolEntry describe_tool(const std::string& tool_id) {
  io::ToolEntry entry;
  entry.id = tool_id;
  if (auto it = known_tools().find(tool_id); it != known_tools().end()) {
    entry.name = it->second.name;
    entry.kind = it->second.kind;
    return entry;
  }
  // Printed tools: material + tip diameter in mm, optionally a design variant.
  static const std::regex printed(R"(^(vero|DM85|DM95|teflon)(\d)(?:_(nail\d))?$)");
  static const std::regex pen_holder(R"(^penh_(vero|DM85|DM95)$)");
  std::smatch match;
  if (std::regex_match(tool_id, match, printed)) {
    entry.kind = "printed";
    entry.material = match[1];
    entry.tip_diameter_m = std::stod(match[2]) * 1e-3;
    entry.name = material_name(entry.material) + ", " + std::string(match[2]) + " mm tip";
    if (match[3].matched) entry.name += " (" + std::string(match[3]) + " variant)";
    return entry;
  }
  if (std::regex_match(tool_id, match, pen_holder)) {
    entry.kind = "printed";
    entry.material = match[1];
    entry.name = material_name(entry.material) + " in a pen holder";
    return entry;
  }
  // A lab's print of one material: "<material>-<tip>mm" ("PLA-1mm", "TPU-95A-0.8mm"), the material
  // as its table names it. A recording's name keeps '-' and '.' in a tool id and no '_'.
  static const std::regex lab_print(R"(^([A-Za-z][A-Za-z0-9.+-]*)-(\d+(?:\.\d+)?)mm$)");
  if (std::regex_match(tool_id, match, lab_print)) {
    entry.kind = "printed";
    entry.material = match[1];
    entry.tip_diameter_m = std::stod(match[2]) * 1e-3;
    entry.name = entry.material + ", " + std::string(match[2]) + " mm tip (printed whole)";
    return entry;
  }
  entry.name = tool_id;
  entry.kind = "unknown";
  return entry;
}

io::SurfaceEntry describe_surface(const std::string& surface_id) {
  static const std::map<std::string, std::string> surfaces = {
      {"office", "80 g office paper"},
      {"note", "rough sketch/note paper"},
      {"stone", "stone paper"},
      {"glass", "glass"},
      {"protector", "plastic screen protector"},
      {"paperlike", "PaperLike screen cover"},
      {"oil", "oiled acrylic (reference)"},
  };
  auto it = surfaces.find(surface_id);
  return io::SurfaceEntry{surface_id, it != surfaces.end() ? it->second : surface_id};
}

}  // namespace nibrig::model::catalog
