// What each bundled printer refuses to make, and why: a material it lacks, a mix it cannot mix
// (with the substitutes it can print offered), more materials than a print holds, a tip below its
// nozzle or a few of its pixels, a stylus beyond its build volume.
#include "model/design/printability.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "model/io/bundled_assets.hpp"
#include "model/mechanics/material_table.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::design {
namespace {

using ::testing::HasSubstr;

// A stylus of the given length along x, 10 mm wide, as boxes: the checks read the regions'
// materials and extent, not their shape.
io::SurfaceMesh printability_box(const std::string& name, double x0, double x1) {
  io::SurfaceMesh m;
  m.name = name;
  for (int i = 0; i < 8; ++i)
    m.vertices.push_back({i & 1 ? x1 : x0, i & 2 ? 0.005 : -0.005, i & 4 ? 0.005 : -0.005});
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

StylusPrint printability_print(const std::string& body, const std::vector<MaterialShare>& tip,
                               double tip_mm, double length = 0.136) {
  StylusPrint p;
  p.point.mix = tip;
  p.point.tip_diameter_m = tip_mm * 1e-3;
  p.regions.push_back(
      {printability_box("body", 0.0, length - 0.006), body, {{catalog_material_name(body), 1.0}}});
  if (!tip.empty())
    p.regions.push_back({printability_box("tip", length - 0.006, length),
                         tip.size() == 1 ? tip[0].material : "mix", tip});
  return p;
}

std::string refusal_of(const io::PrinterProfile& printer, const StylusPrint& print) {
  try {
    check_printable(printer, print);
  } catch (const PrintRefused& e) {
    return e.what();
  }
  return "";
}

TEST(Printability, TheFdmPrinterMakesItsOwnMaterialsAndRefusesThePapers) {
  const auto mk3s = io::find_printer_profile("prusa-mk3s");
  EXPECT_EQ(refusal_of(mk3s, printability_print("PLA", {{"PLA", 1.0}}, 2.0)), "");
  EXPECT_THAT(refusal_of(mk3s, printability_print("VeroClear-Piovarci2018", {{"vero", 1.0}}, 2.0)),
              HasSubstr("the body and tip need vero (VeroClear-Piovarci2018), which prusa-mk3s "
                        "does not have (it prints PLA, PETG, TPU-95A)"));
  const auto mix = refusal_of(
      mk3s, printability_print("VeroClear-Piovarci2018", {{"DM85", 0.62}, {"vero", 0.38}}, 2.7));
  EXPECT_THAT(mix, HasSubstr("prusa-mk3s (FDM) cannot print"));
  EXPECT_THAT(mix, HasSubstr("cannot mix materials"));
  EXPECT_THAT(refusal_of(mk3s, printability_print("PLA", {{"PETG", 1.0}}, 2.0)),
              HasSubstr("needs 2 materials in one print and prusa-mk3s holds 1"));
  // The stock 0.4 mm nozzle: a 0.3 mm tip is below it, 0.4 mm is not.
  EXPECT_THAT(refusal_of(mk3s, printability_print("PLA", {{"PLA", 1.0}}, 0.3)),
              HasSubstr("the 0.3 mm tip is narrower than its 0.4 mm nozzle"));
  EXPECT_EQ(refusal_of(mk3s, printability_print("PLA", {{"PLA", 1.0}}, 0.4)), "");
}

TEST(Printability, ALabsMaterialIsPrintedAsTheMaterialItsBarWasPrintedIn) {
  StylusPrint lab = printability_print("lab-pla", {{"lab-pla", 1.0}}, 2.0);
  mechanics::Material calibrated =
      mechanics::read_material_file(io::default_materials()).find("PLA");
  calibrated.name = "lab-pla";
  calibrated.printed_as = "PLA";
  lab.materials = mechanics::MaterialTable({calibrated});
  EXPECT_EQ(refusal_of(io::find_printer_profile("prusa-mk3s"), lab), "");
  EXPECT_THAT(refusal_of(io::find_printer_profile("prusa-sl1s"), lab),
              HasSubstr("need lab-pla (printed as PLA), which prusa-sl1s does not have"));
}

TEST(Printability, TheMslaPrinterRefusesATipBelowFourPixelsAndAStylusTallerThanItsVat) {
  const auto sl1s = io::find_printer_profile("prusa-sl1s");
  EXPECT_EQ(refusal_of(sl1s, printability_print("resin-standard", {{"resin-standard", 1.0}}, 2.0)),
            "");
  // 4 pixels of 0.05 mm: 0.2 mm.
  EXPECT_THAT(
      refusal_of(sl1s, printability_print("resin-standard", {{"resin-standard", 1.0}}, 0.15)),
      HasSubstr("narrower than 4 of its 0.05 mm pixels (0.2 mm)"));
  EXPECT_EQ(refusal_of(sl1s, printability_print("resin-standard", {{"resin-standard", 1.0}}, 0.2)),
            "");
  // Standing, the stylus's length is its height: 160 mm is beyond the SL1S's 150.
  EXPECT_THAT(
      refusal_of(sl1s, printability_print("resin-standard", {{"resin-standard", 1.0}}, 2.0, 0.160)),
      HasSubstr("standing the stylus is 160.0 mm along z, beyond the 150 mm build volume"));
  EXPECT_THAT(refusal_of(sl1s, printability_print("PLA", {{"PLA", 1.0}}, 2.0)),
              HasSubstr("which prusa-sl1s does not have"));
}

TEST(Printability, ThePapersPolyJetMixesWhatTheOthersCannot) {
  const auto connex = io::find_printer_profile("stratasys-objet260-connex");
  EXPECT_EQ(refusal_of(connex, printability_print("VeroClear-Piovarci2018",
                                                  {{"DM85", 0.62}, {"vero", 0.38}}, 2.7)),
            "");
  EXPECT_EQ(refusal_of(connex, printability_print("VeroClear-Piovarci2018", {{"DM95", 1.0}}, 1.0)),
            "");
  EXPECT_THAT(refusal_of(connex, printability_print("PLA", {{"PLA", 1.0}}, 2.0)),
              HasSubstr("need PLA, which stratasys-objet260-connex does not have"));
}

TEST(Printability, AMixOnAPrinterThatCannotMixOffersTheSubstitutesItHas) {
  // A PolyJet that prints VeroClear and DM85 but no digital-material mixes: a lab's own profile.
  std::ifstream in(nibrig::test::assets_dir() / "printers" / "stratasys-objet260-connex.json");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text.replace(text.find("\"mixes_materials\": true"), 23, "\"mixes_materials\": false");
  const auto file = nibrig::test::scratch_dir("printability") / "no-mix.json";
  std::ofstream(file) << text;
  const auto no_mix = io::read_printer_profile(file);
  auto print = printability_print("VeroClear-Piovarci2018", {{"DM85", 0.62}, {"vero", 0.38}}, 2.7);
  Substitute dm85, teflon;
  dm85.point = {{{"DM85", 1.0}}, 2.7e-3};
  dm85.cost = 0.41, dm85.cost_sd = 0.05;
  teflon.point = {{{"teflon", 1.0}}, 2.7e-3};  // not a material this printer has: not offered
  teflon.cost = 0.2;
  print.substitutes = {teflon, dm85};
  const auto why = refusal_of(no_mix, print);
  EXPECT_THAT(why, HasSubstr("cannot mix materials"));
  EXPECT_THAT(why, HasSubstr("without mixing, stratasys-objet260-connex can print DM85:1,tip=2.7mm "
                             "(0.410 ± 0.050 from the design in the space)"));
  EXPECT_EQ(why.find("teflon"), std::string::npos) << why;
}

TEST(Printability, ALineOfDesignsIsPrintableWhenAnEndIs) {
  const auto mk3s = io::find_printer_profile("prusa-mk3s");
  const auto connex = io::find_printer_profile("stratasys-objet260-connex");
  const auto vero = parse_design_point("vero,tip=1mm"), dm85 = parse_design_point("DM85,tip=4mm");
  EXPECT_THAT(unprintable_line(mk3s, vero, dm85),
              HasSubstr("it lacks vero, DM85 (it prints PLA, PETG, TPU-95A)"));
  EXPECT_EQ(unprintable_line(connex, vero, dm85), "");
  EXPECT_EQ(unprintable_line(mk3s, parse_design_point("PLA,tip=1mm"), dm85), "")
      << "the PLA end prints";
}

}  // namespace
}  // namespace nibrig::model::design
