#include "model/design/printability.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <set>

#include "model/design/design_point.hpp"

namespace nibrig::model::design {
namespace {

std::string printability_lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string printability_list(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// The stylus's extent along x, y, z as the printer's orientation puts it on the bed.
std::array<double, 3> printed_extent(const StylusPrint& print, const std::string& orientation) {
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (const auto& region : print.regions)
    for (const auto& v : region.surface.vertices)
      for (std::size_t k = 0; k < 3; ++k)
        lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
  const std::array<double, 3> along{hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
  if (orientation == "standing") return {along[2], along[1], along[0]};
  return along;
}

// What a printer loads for a material: a lab's own is the bundled material it was printed in.
std::string loaded_material(const StylusPrint& print, const std::string& material) {
  const std::string wanted = printability_lower(catalog_material_name(material));
  for (const auto& m : print.materials.materials())
    if (printability_lower(m.name) == wanted && !m.printed_as.empty()) return m.printed_as;
  return material;
}

}  // namespace

bool printer_has(const io::PrinterProfile& printer, const std::string& material) {
  const std::string wanted = printability_lower(catalog_material_name(material));
  return std::any_of(printer.materials.begin(), printer.materials.end(), [&](const std::string& m) {
    return printability_lower(catalog_material_name(m)) == wanted;
  });
}

double smallest_tip_m(const io::PrinterProfile& printer) {
  switch (printer.process) {
    case io::PrintProcess::fdm:
      return printer.nozzle_diameter_m;
    case io::PrintProcess::msla:
      return printer.min_feature_pixels * printer.pixel_size_m();
    case io::PrintProcess::polyjet:
      return printer.xy_resolution_m;
  }
  return 0.0;
}

std::vector<std::string> print_refusals(const io::PrinterProfile& printer,
                                        const StylusPrint& print) {
  std::vector<std::string> reasons;
  const std::string has = "it prints " + printability_list(printer.materials);
  std::set<std::string> loaded;  // distinct materials the print needs loaded
  // Each material the printer lacks, once, with the regions that need it.
  std::vector<std::pair<std::string, std::string>> missing;  // material (its table name), regions
  bool refused_mix = false;
  for (const auto& region : print.regions) {
    const std::string& name = region.surface.name;
    if (region.mix.size() > 1 && !printer.mixes_materials) {
      std::string shares;
      for (const auto& share : region.mix)
        shares += fmt::format("{}{} {:.0f} %", shares.empty() ? "" : " + ", share.material,
                              100.0 * share.fraction);
      reasons.push_back(fmt::format(
          "the {} is a mix ({}) and {} cannot mix materials: only a PolyJet printer dithers "
          "digital materials",
          name, shares, printer.name));
      refused_mix = true;
    }
    for (const auto& share : region.mix) {
      const std::string as = loaded_material(print, share.material);
      loaded.insert(printability_lower(catalog_material_name(as)));
      if (printer_has(printer, as)) continue;
      const std::string material = as != share.material
                                       ? share.material + " (printed as " + as + ")"
                                   : region.mix.size() == 1 && region.material != share.material
                                       ? share.material + " (" + region.material + ")"
                                       : share.material;
      auto it = std::find_if(missing.begin(), missing.end(), [&](const auto& m) {
        return printability_lower(catalog_material_name(share.material)) ==
               printability_lower(catalog_material_name(m.first.substr(0, m.first.find(' '))));
      });
      if (it == missing.end())
        missing.emplace_back(material, name);
      else
        it->second += " and " + name;
    }
  }
  for (const auto& [material, regions] : missing)
    reasons.push_back(fmt::format("the {} need{} {}, which {} does not have ({})", regions,
                                  regions.find(" and ") == std::string::npos ? "s" : "", material,
                                  printer.name, has));
  if (static_cast<int>(loaded.size()) > printer.materials_per_print)
    reasons.push_back(fmt::format("the stylus needs {} materials in one print and {} holds {}",
                                  loaded.size(), printer.name, printer.materials_per_print));
  const double tip = print.point.tip_diameter_m, smallest = smallest_tip_m(printer);
  if (tip < smallest) {
    const std::string what =
        printer.process == io::PrintProcess::fdm ? fmt::format("its {:g} mm nozzle", smallest * 1e3)
        : printer.process == io::PrintProcess::msla
            ? fmt::format("{} of its {:g} mm pixels ({:g} mm)", printer.min_feature_pixels,
                          printer.pixel_size_m() * 1e3, smallest * 1e3)
            : fmt::format("its {:g} mm dot pitch", smallest * 1e3);
    reasons.push_back(fmt::format("the {:g} mm tip is narrower than {}", tip * 1e3, what));
  }
  const auto extent = printed_extent(print, printer.orientation);
  for (std::size_t k = 0; k < 3; ++k)
    if (extent[k] > printer.build_volume_m[k]) {
      reasons.push_back(fmt::format(
          "{} the stylus is {:.1f} mm along {}, beyond the {:g} mm build volume",
          printer.orientation, extent[k] * 1e3, "xyz"[k], printer.build_volume_m[k] * 1e3));
      break;
    }
  if (refused_mix) {
    std::string offered;
    for (const auto& s : print.substitutes)
      if (std::all_of(s.point.mix.begin(), s.point.mix.end(),
                      [&](const MaterialShare& m) { return printer_has(printer, m.material); }))
        offered += fmt::format("{}{} ({:.3f} ± {:.3f} from the design in the space)",
                               offered.empty() ? "" : ", ", to_string(s.point), s.cost, s.cost_sd);
    if (!offered.empty())
      reasons.push_back("without mixing, " + printer.name + " can print " + offered);
  }
  return reasons;
}

std::string unprintable_line(const io::PrinterProfile& printer, const DesignPoint& a,
                             const DesignPoint& b) {
  const auto has_all = [&](const DesignPoint& p) {
    return std::all_of(p.mix.begin(), p.mix.end(),
                       [&](const MaterialShare& m) { return printer_has(printer, m.material); });
  };
  if (has_all(a) || has_all(b)) return "";  // an end at least; between them only a mixing printer
  std::vector<std::string> lacking;
  for (const auto* p : {&a, &b})
    for (const auto& m : p->mix)
      if (!printer_has(printer, m.material) &&
          std::find(lacking.begin(), lacking.end(), m.material) == lacking.end())
        lacking.push_back(m.material);
  return fmt::format("{} has neither end of the line between {} and {}: it lacks {} (it prints {})",
                     printer.name, label(a), label(b), printability_list(lacking),
                     printability_list(printer.materials));
}

void check_printable(const io::PrinterProfile& printer, const StylusPrint& print) {
  const auto reasons = print_refusals(printer, print);
  if (reasons.empty()) return;
  std::string message = fmt::format("{} ({}) cannot print {}: ", printer.name,
                                    io::process_name(printer.process), label(print.point));
  for (std::size_t i = 0; i < reasons.size(); ++i) message += (i ? "; " : "") + reasons[i];
  throw PrintRefused(message);
}

}  // namespace nibrig::model::design
