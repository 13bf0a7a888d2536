// Printer profiles: every bundled one reads with a source for each value, a lab's own is found by
// name in the user's folder, and a profile that would not print the modelled solid is refused with
// the file and field named.
#include "model/io/printer_profile.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "model/io/format_error.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::io {
namespace {

using ::testing::HasSubstr;

// The bundled FDM profile's text with `from` replaced by `to`: one fault at a time.
std::filesystem::path printer_variant(const std::string& name, const std::string& from, const std::string& to) {
  std::ifstream in(nibrig::test::assets_dir() / "printers" / "prusa-mk3s.json");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto at = text.find(from);
  if (at == std::string::npos) throw std::runtime_error("no '" + from + "' in prusa-mk3s.json");
  text.replace(at, from.size(), to);
  const auto file = nibrig::test::scratch_dir("printer_profile") / (name + ".json");
  std::ofstream(file) << text;
  return file;
}

std::string printer_refusal(const std::filesystem::path& file) {
  try {
    read_printer_profile(file);
  } catch (const FormatError& e) {
    return e.what();
  }
  return "(read without an error)";
}

TEST(PrinterProfile, TheBundledProfilesReadEachProcessOnce) {
  const auto names = bundled_printer_names();
  ASSERT_EQ(names.size(), 3u);
  std::vector<PrintProcess> processes;
  for (const auto& name : names) {
    const auto p = find_printer_profile(name);
    EXPECT_EQ(p.name, name) << "a profile's name is its file's";
    EXPECT_FALSE(p.materials.empty());
    EXPECT_FALSE(p.orientation_reason.empty());
    processes.push_back(p.process);
  }
  EXPECT_THAT(processes, ::testing::UnorderedElementsAre(PrintProcess::fdm, PrintProcess::msla, PrintProcess::polyjet));
  const auto fdm = find_printer_profile("prusa-mk3s");
  EXPECT_EQ(fdm.slicer_setting("fill_density"), "100%");
  EXPECT_FALSE(fdm.mixes_materials);
  const auto msla = find_printer_profile("prusa-sl1s");
  // The SL1S's mask: 128 mm over 2560 pixels (PrusaSlicer's own profile), 0.05 mm a pixel.
  EXPECT_NEAR(msla.pixel_size_m(), 0.05e-3, 1e-12);
  EXPECT_EQ(msla.orientation, "standing");
  const auto polyjet = find_printer_profile("stratasys-objet260-connex");
  EXPECT_TRUE(polyjet.mixes_materials);
  EXPECT_TRUE(polyjet.slicer_settings.empty());
}

TEST(PrinterProfile, AFdmProfileThatWouldNotPrintASolidIsRefusedNamingTheField) {
  // PrusaSlicer 2.5 reads "100" without its sign, and 100 % with the profile's gyroid, as 20 %.
  EXPECT_THAT(printer_refusal(printer_variant("no_sign", "\"fill_density\": \"100%\"", "\"fill_density\": \"100\"")),
              HasSubstr("slicer_settings.fill_density"));
  EXPECT_THAT(printer_refusal(printer_variant("gyroid", "\"fill_pattern\": \"rectilinear\"", "\"fill_pattern\": \"gyroid\"")),
              HasSubstr("'gyroid' cannot fill 100 %"));
  EXPECT_THAT(printer_refusal(printer_variant("sparse", "\"fill_density\": \"100%\"", "\"fill_density\": \"20%\"")),
              HasSubstr("expected \"100%\""));
}

TEST(PrinterProfile, EveryValueNeedsItsSourceAndTheGeometryIsWrittenOnce) {
  const auto unsourced = printer_variant("unsourced", "\"slicer_settings.perimeters\":", "\"slicer_settings.walls\":");
  EXPECT_THAT(printer_refusal(unsourced), HasSubstr("no source for 'slicer_settings.perimeters'"));
  const auto twice = printer_variant("twice", "\"perimeters\": \"2\",", "\"perimeters\": \"2\", \"layer_height\": \"0.2\",");
  EXPECT_THAT(printer_refusal(twice), HasSubstr("'layer_height' comes from the profile's own fields"));
  const auto process = printer_variant("process", "\"process\": \"fdm\"", "\"process\": \"sls\"");
  EXPECT_THAT(printer_refusal(process), HasSubstr("field 'process'"));
  const auto nozzle = printer_variant("nozzle", "\"nozzle_diameter_mm\": 0.4", "\"nozzle_diameter_mm\": 40");
  EXPECT_THAT(printer_refusal(nozzle), HasSubstr("nozzle_diameter_mm"));
}

TEST(PrinterProfile, ALabsOwnProfileIsFoundByNameAndAnUnknownNameListsTheKnownOnes) {
  const auto folder = nibrig::test::scratch_dir("printer_profile_user");
  ::setenv("NIBRIG_PRINTERS", folder.c_str(), 1);
  const auto mine = printer_variant("mine", "\"name\": \"prusa-mk3s\"", "\"name\": \"lab-mk3s\"");
  std::filesystem::copy_file(mine, folder / "lab-mk3s.json", std::filesystem::copy_options::overwrite_existing);
  EXPECT_EQ(find_printer_profile("lab-mk3s").name, "lab-mk3s");
  EXPECT_EQ(find_printer_profile(mine.string()).file, mine) << "a file is read as given";
  try {
    find_printer_profile("ultimaker");
    ADD_FAILURE() << "an unknown printer was found";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), HasSubstr("prusa-mk3s"));
    EXPECT_THAT(e.what(), HasSubstr("lab-mk3s"));
  }
  ::unsetenv("NIBRIG_PRINTERS");
}

}  // namespace
}  // namespace nibrig::model::io
