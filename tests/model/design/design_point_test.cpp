#include "model/design/design_point.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <stdexcept>

namespace nibrig::model::design {
namespace {

using ::testing::HasSubstr;

std::string error_of(const std::string& text) {
  try {
    parse_design_point(text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

TEST(DesignPoint, ReadsTheIssuesExampleAndWritesItBack) {
  const DesignPoint p = parse_design_point("DM85:0.25,vero:0.75,tip=1mm");
  ASSERT_EQ(p.mix.size(), 2u);
  EXPECT_EQ(p.mix[0].material, "DM85");
  EXPECT_DOUBLE_EQ(p.fraction_of("DM85"), 0.25);
  EXPECT_DOUBLE_EQ(p.fraction_of("vero"), 0.75);
  EXPECT_DOUBLE_EQ(p.fraction_of("DM95"), 0.0);
  EXPECT_DOUBLE_EQ(p.tip_diameter_m, 0.001);
  EXPECT_EQ(label(DesignPoint{{{"vero", 0.0477458}, {"DM85", 0.9522542}}, 0.00385676}),
            "vero:0.0477,DM85:0.952,tip=3.86mm");
  const DesignPoint again = parse_design_point(to_string(p));
  EXPECT_EQ(to_string(again), to_string(p));
  EXPECT_DOUBLE_EQ(again.tip_diameter_m, p.tip_diameter_m);
}

TEST(DesignPoint, OneMaterialNeedsNoFractionAndSpacesAreAllowed) {
  const DesignPoint p = parse_design_point(" vero , tip=2.5mm ");
  ASSERT_EQ(p.mix.size(), 1u);
  EXPECT_DOUBLE_EQ(p.mix[0].fraction, 1.0);
  EXPECT_DOUBLE_EQ(p.tip_diameter_m, 0.0025);
}

TEST(DesignPoint, MaterialNamesInAnyCaseAndTheMaterialTablesFullNames) {
  // `mechanics --material Steel` is accepted; a design point should be as forgiving, and the
  // material table's names should reach the catalog's: the forcing model knows only vero, DM95,
  // DM85 and teflon.
  const DesignPoint p = parse_design_point("dm85:0.5,VeroClear-Piovarci2018:0.5,tip=2mm");
  ASSERT_EQ(p.mix.size(), 2u);
  EXPECT_EQ(p.mix[0].material, "DM85");
  EXPECT_EQ(p.mix[1].material, "vero");
  EXPECT_EQ(parse_design_point("VeroClear,tip=2mm").mix[0].material, "vero");
  EXPECT_EQ(parse_design_point("TEFLON-taped,tip=2mm").mix[0].material, "teflon");
  EXPECT_EQ(catalog_material_name("unobtainium"), "unobtainium") << "left for the model to refuse";
  // Two spellings of one material are one material named twice.
  EXPECT_THROW(parse_design_point("vero:0.5,VEROCLEAR:0.5,tip=2mm"), std::invalid_argument);
}

TEST(DesignPoint, RefusesWhatIsNotADesignSayingWhy) {
  EXPECT_THAT(error_of("DM85:0.3,vero:0.6,tip=1mm"), HasSubstr("add up to 0.9, expected 1"));
  EXPECT_THAT(error_of("DM85:1.5,tip=1mm"), HasSubstr("fraction of 'DM85' is 1.5"));
  EXPECT_THAT(error_of("DM85:0.5,DM85:0.5,tip=1mm"), HasSubstr("twice"));
  EXPECT_THAT(error_of("vero"), HasSubstr("no tip diameter"));
  EXPECT_THAT(error_of("vero,tip=1"), HasSubstr("tip=<number>mm"));
  EXPECT_THAT(error_of("vero,tip=-1mm"), HasSubstr("positive"));
  EXPECT_THAT(error_of("vero:half,tip=1mm"), HasSubstr("not a number"));
  EXPECT_THAT(error_of("vero,,tip=1mm"), HasSubstr("empty entry"));
  EXPECT_THAT(error_of("tip=1mm"), HasSubstr("no material"));
  EXPECT_THAT(error_of("vero,tip=1mm,tip=2mm"), HasSubstr("twice"));
}

TEST(DesignPoint, TheLineBetweenTwoDesignsInterpolatesFractionsAndTip) {
  const DesignPoint a = parse_design_point("vero,tip=1mm");
  const DesignPoint b = parse_design_point("DM85,tip=4mm");
  const DesignPoint quarter = interpolate(a, b, 0.25);
  EXPECT_DOUBLE_EQ(quarter.fraction_of("vero"), 0.75);
  EXPECT_DOUBLE_EQ(quarter.fraction_of("DM85"), 0.25);
  EXPECT_DOUBLE_EQ(quarter.tip_diameter_m, 0.00175);
  EXPECT_NO_THROW(validate(quarter));
  EXPECT_EQ(interpolate(a, b, 0.0).mix.size(), 1u);  // a material at fraction 0 is not listed
  EXPECT_THROW(interpolate(a, b, 1.5), std::invalid_argument);
}

// Issue 46: "DM85:1e-320,vero:1" printed as a "DM85 0 %" mix; a share the sheet's whole per cent
// shows as 0 is refused, and the smallest it shows is taken.
TEST(DesignPointMinimumShare, RefusesAShareThatPrintsAsZeroPercent) {
  try {
    parse_design_point("DM85:1e-320,vero:1,tip=2mm");
    FAIL() << "a 1e-320 share passed";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("below 0.005"), std::string::npos) << e.what();
  }
  const DesignPoint p = parse_design_point("DM85:0.005,vero:0.995,tip=2mm");
  EXPECT_EQ(p.fraction_of("DM85"), 0.005);  // exactly as typed: no arithmetic between
}

}  // namespace
}  // namespace nibrig::model::design
