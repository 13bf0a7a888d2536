#include "model/io/printer_profile.hpp"

#include <algorithm>
#include <cctype>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "model/io/bundled_assets.hpp"
#include "model/io/format_error.hpp"
#include "model/io/json_fields.hpp"
#include "model/io/user_store.hpp"

namespace nibrig::model::io {
namespace {

namespace jf = json_fields;

// The patterns PrusaSlicer 2.5 fills at 100 % (its top/bottom fill patterns). With any other, a
// 3MF's "fill_density = 100%" is dropped for the default 20 % without a word (found by slicing:
// tests/ui/cli/export_printer_cli_test.cpp), and --load refuses it.
constexpr const char* kPrinterSolidFillPatterns[] = {"rectilinear",  "monotonic",        "alignedrectilinear", "concentric",
                                                     "hilbertcurve", "archimedeanchords", "octagramspiral"};

double printer_mm(const nlohmann::json& object, const std::string& key, const std::filesystem::path& file,
                  double low_mm, double high_mm, const std::string& why) {
  return 1e-3 * jf::as_number_in(jf::member(object, key, file, ""), file, key, low_mm, high_mm, why);
}

bool printer_safe_text(const std::string& text) {
  return std::none_of(text.begin(), text.end(), [](unsigned char c) { return c == '\n' || c == '\r' || c == 0; });
}

}  // namespace

std::string process_name(PrintProcess process) {
  switch (process) {
    case PrintProcess::fdm: return "FDM";
    case PrintProcess::msla: return "MSLA";
    case PrintProcess::polyjet: return "PolyJet";
  }
  return "?";
}

double PrinterProfile::pixel_size_m() const {
  return process == PrintProcess::msla && display_pixels[0] > 0 ? display_m[0] / display_pixels[0] : 0.0;
}

std::string PrinterProfile::slicer_setting(const std::string& key) const {
  for (const auto& [k, v] : slicer_settings)
    if (k == key) return v;
  return {};
}

std::string PrinterProfile::source_of(const std::string& key) const {
  for (const auto& [k, v] : sources)
    if (k == key) return v;
  return {};
}

PrinterProfile read_printer_profile(const std::filesystem::path& file) {
  const nlohmann::json root = jf::parse_file(file);
  jf::as_object(root, file, "");
  jf::check_format_and_version(root, file, "nibrig-printer", 1);
  PrinterProfile p;
  p.file = file;
  p.name = jf::string_member(root, "name", file, "");
  if (p.name.empty()) throw FormatError(file, jf::place("name"), "the name is empty");
  p.printer = jf::string_member(root, "printer", file, "");
  const std::string process = jf::string_member(root, "process", file, "");
  if (process == "fdm") p.process = PrintProcess::fdm;
  else if (process == "msla") p.process = PrintProcess::msla;
  else if (process == "polyjet") p.process = PrintProcess::polyjet;
  else throw FormatError(file, jf::place("process"), "'" + process + "' is not a process (expected fdm, msla or polyjet)");

  const auto& materials = jf::as_array(jf::member(root, "materials", file, ""), file, "materials");
  if (materials.empty()) throw FormatError(file, jf::place("materials"), "a printer needs at least one material");
  for (std::size_t i = 0; i < materials.size(); ++i)
    p.materials.push_back(jf::as_string(materials[i], file, jf::element_path("materials", i)));
  const auto& mixes = jf::member(root, "mixes_materials", file, "");
  if (!mixes.is_boolean()) throw FormatError(file, jf::place("mixes_materials"), "expected true or false");
  p.mixes_materials = mixes.get<bool>();
  p.materials_per_print = static_cast<int>(
      jf::as_integer(jf::member(root, "materials_per_print", file, ""), file, "materials_per_print", 1, 16));

  const auto volume = jf::as_number_array_in(jf::member(root, "build_volume_mm", file, ""), file, "build_volume_mm",
                                             1.0, 5000.0, "a printer's build volume in millimetres");
  if (volume.size() != 3) throw FormatError(file, jf::place("build_volume_mm"), "expected [x, y, z] in millimetres");
  for (int k = 0; k < 3; ++k) p.build_volume_m[static_cast<std::size_t>(k)] = 1e-3 * volume[static_cast<std::size_t>(k)];
  p.orientation = jf::string_member(root, "orientation", file, "");
  if (p.orientation != "lying" && p.orientation != "standing")
    throw FormatError(file, jf::place("orientation"), "'" + p.orientation + "' is not lying or standing");
  p.orientation_reason = jf::string_member(root, "orientation_reason", file, "");
  p.supports = jf::string_member(root, "supports", file, "");
  p.post_process = jf::string_member(root, "post_process", file, "");
  p.slicer = jf::string_member(root, "slicer", file, "");
  p.layer_height_m = printer_mm(root, "layer_height_mm", file, 0.001, 1.0, "a layer of 1 µm to 1 mm");

  std::vector<std::string> numbers = {"build_volume_mm", "layer_height_mm"};
  switch (p.process) {
    case PrintProcess::fdm:
      p.nozzle_diameter_m = printer_mm(root, "nozzle_diameter_mm", file, 0.05, 3.0, "a nozzle of 0.05 to 3 mm");
      numbers.push_back("nozzle_diameter_mm");
      break;
    case PrintProcess::msla: {
      const auto display = jf::as_number_array_in(jf::member(root, "display_mm", file, ""), file, "display_mm", 1.0,
                                                   1000.0, "a masking display's size in millimetres");
      const auto pixels = jf::as_number_array_in(jf::member(root, "display_pixels", file, ""), file, "display_pixels",
                                                 1.0, 100000.0, "a display's pixel count");
      if (display.size() != 2 || pixels.size() != 2)
        throw FormatError(file, jf::place("display_mm"), "display_mm and display_pixels are [width, height]");
      for (std::size_t k = 0; k < 2; ++k) {
        p.display_m[k] = 1e-3 * display[k];
        p.display_pixels[k] = static_cast<int>(pixels[k]);
        if (p.display_pixels[k] != pixels[k])
          throw FormatError(file, jf::place(jf::element_path("display_pixels", k)), "a pixel count is a whole number");
      }
      p.min_feature_pixels = static_cast<int>(
          jf::as_integer(jf::member(root, "min_feature_pixels", file, ""), file, "min_feature_pixels", 1, 100));
      for (const char* k : {"display_mm", "display_pixels", "min_feature_pixels"}) numbers.push_back(k);
      break;
    }
    case PrintProcess::polyjet:
      p.xy_resolution_m = printer_mm(root, "xy_resolution_mm", file, 0.001, 1.0, "a dot pitch of 1 µm to 1 mm");
      numbers.push_back("xy_resolution_mm");
      break;
  }

  const auto& settings = jf::as_object(jf::member(root, "slicer_settings", file, ""), file, "slicer_settings");
  for (const auto& [key, value] : settings.items()) {
    const std::string path = jf::member_path("slicer_settings", key);
    const bool key_ok = !key.empty() && std::all_of(key.begin(), key.end(), [](unsigned char c) {
      return std::islower(c) || std::isdigit(c) || c == '_';
    });
    if (!key_ok) throw FormatError(file, jf::place(path), "a slicer key is lower-case letters, digits and '_'");
    // The printer's geometry is written from the profile's own fields (slicer_settings.hpp), once.
    for (const char* own : {"printer_technology", "nozzle_diameter", "layer_height", "bed_shape", "max_print_height",
                            "display_width", "display_height", "display_pixels_x", "display_pixels_y"})
      if (key == own)
        throw FormatError(file, jf::place(path), "'" + key + "' comes from the profile's own fields, not slicer_settings");
    const std::string text = jf::as_string(value, file, path);
    if (!printer_safe_text(text)) throw FormatError(file, jf::place(path), "a slicer value is one line");
    p.slicer_settings.emplace_back(key, text);
    numbers.push_back(path);
  }

  const auto& sources = jf::as_object(jf::member(root, "sources", file, ""), file, "sources");
  for (const auto& [key, value] : sources.items())
    p.sources.emplace_back(key, jf::as_string(value, file, jf::member_path("sources", key)));
  for (const auto& key : numbers)
    if (p.source_of(key).empty())
      throw FormatError(file, jf::place("sources"), "no source for '" + key + "' (every value says where it comes from)");

  if (p.process == PrintProcess::fdm) {
    // The experiment behind these: PrusaSlicer 2.5 keeps its 20 % otherwise (kPrinterSolidFillPatterns).
    if (p.slicer_setting("fill_density") != "100%")
      throw FormatError(file, jf::place("slicer_settings.fill_density"),
                        "an FDM profile prints the modelled solid: expected \"100%\" (with the per cent sign), found \"" +
                            p.slicer_setting("fill_density") + "\"");
    const std::string pattern = p.slicer_setting("fill_pattern");
    if (std::find(std::begin(kPrinterSolidFillPatterns), std::end(kPrinterSolidFillPatterns), pattern) ==
        std::end(kPrinterSolidFillPatterns))
      throw FormatError(file, jf::place("slicer_settings.fill_pattern"),
                        "'" + pattern + "' cannot fill 100 % in PrusaSlicer, which then prints 20 % infill "
                        "(expected rectilinear, monotonic, alignedrectilinear, concentric, hilbertcurve, "
                        "archimedeanchords or octagramspiral)");
  }
  return p;
}

std::filesystem::path user_printers_folder() { return user_store_folder("NIBRIG_PRINTERS", "printers"); }

std::vector<std::string> bundled_printer_names() {
  std::vector<std::string> names;
  std::error_code error;
  const auto folder = assets_dir() / "printers";
  for (const auto& entry : std::filesystem::directory_iterator(folder, error))
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

PrinterProfile find_printer_profile(const std::string& name_or_file) {
  std::error_code error;
  if (std::filesystem::is_regular_file(name_or_file, error)) return read_printer_profile(name_or_file);
  const auto own = user_store_file(user_printers_folder(), name_or_file, "printer");
  if (std::filesystem::is_regular_file(own, error)) return read_printer_profile(own);
  const auto bundled = assets_dir() / "printers" / (name_or_file + ".json");
  if (name_or_file.find('/') == std::string::npos && std::filesystem::is_regular_file(bundled, error))
    return read_printer_profile(bundled);
  std::string known;
  for (const auto& n : bundled_printer_names()) known += (known.empty() ? "" : ", ") + n;
  std::string mine;
  for (const auto& entry : std::filesystem::directory_iterator(user_printers_folder(), error))
    if (entry.path().extension() == ".json") mine += (mine.empty() ? "" : ", ") + entry.path().stem().string();
  throw std::invalid_argument("no printer profile '" + name_or_file + "': neither a file nor a name (bundled: " + known +
                              "; yours in " + user_printers_folder().string() + ": " + (mine.empty() ? "none" : mine) +
                              ")");
}

}  // namespace nibrig::model::io
