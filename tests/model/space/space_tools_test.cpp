// Every tool the panel draws in a space: the judged stimuli with their bootstrap regions, then every
// other catalog pairing placed from its descriptors with the map's prediction region, each with
// what the catalog says of it.
#include "model/space/space_tools.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "model/space/catalog_descriptors.hpp"
#include "model/space/simulated_study.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::space {
namespace {

const std::filesystem::path& catalog_file() {
  static const std::filesystem::path f = nibrig::test::assets_dir() / "default_catalog.json";
  return f;
}

const io::Catalog& catalog() {
  static const io::Catalog c = io::read_catalog(catalog_file());
  return c;
}

const SpaceFile& space() {
  static const SpaceFile s = [] {
    SimulatedStudyOptions o;
    o.bootstrap_resamples = 6;  // the regions' size is not what these tests check
    return run_simulated_study(catalog(), catalog_file(), o).space;
  }();
  return s;
}

const SpaceTool& find(const SpaceTools& tools, const std::string& pairing) {
  for (const auto& t : tools.tools)
    if (t.pairing == pairing) return t;
  throw std::runtime_error("no tool " + pairing);
}

TEST(SpaceTools, StimuliFirstThenEveryOtherPairingOnce) {
  const SpaceTools tools = space_tools(space(), catalog(), catalog_file());
  std::size_t placeable = 0;
  for (const auto& p : catalog().pairings) placeable += p.friction && p.vibration ? 1 : 0;
  ASSERT_EQ(tools.tools.size(), placeable);  // 15 judged + 47 placed in the demo
  std::set<std::string> names;
  for (std::size_t i = 0; i < tools.tools.size(); ++i) {
    const SpaceTool& t = tools.tools[i];
    EXPECT_EQ(t.judged, i < 15) << t.pairing;
    if (i < 15) {
      EXPECT_EQ(t.pairing, space().stimuli[i]);
    }
    names.insert(t.pairing);
    ASSERT_EQ(t.ellipses.size(), 2u) << t.pairing;
    // The 95 % ellipse holds the 68 % one.
    EXPECT_GT(t.ellipses[1].semi_axis_1, t.ellipses[0].semi_axis_1) << t.pairing;
    EXPECT_GE(t.ellipses[0].semi_axis_1, t.ellipses[0].semi_axis_2) << t.pairing;
    EXPECT_EQ(t.descriptors.size(), 2) << t.pairing;
    ASSERT_TRUE(t.mu.has_value()) << t.pairing;
    EXPECT_DOUBLE_EQ(*t.mu, t.descriptors(0)) << t.pairing;  // axis 1's descriptor is μ itself
  }
  EXPECT_EQ(names.size(), tools.tools.size());
  EXPECT_EQ(tools.levels, (std::vector<double>{0.68, 0.95}));
  EXPECT_EQ(tools.descriptor_names, space().descriptor_names);
}

TEST(SpaceTools, AJudgedStimulusIsAtItsFitWithItsBootstrapRegion) {
  const SpaceTools tools = space_tools(space(), catalog(), catalog_file());
  const SpaceTool& crayon = find(tools, "cryon/office");
  EXPECT_EQ(crayon.kind, ToolKind::real);
  EXPECT_EQ(crayon.tool_id, "cryon");
  EXPECT_EQ(crayon.surface_id, "office");
  EXPECT_NE(crayon.tool_name, "cryon");  // the catalog's name for people
  EXPECT_EQ(crayon.region_source, RegionSource::bootstrap);
  EXPECT_EQ(crayon.position, space().coordinates.col(0));
  const PlaneEllipse e = plane_ellipse(space().regions[0], 1);
  EXPECT_EQ(crayon.ellipses[1].semi_axis_1, e.semi_axis_1);
  EXPECT_EQ(find(tools, "vero1/note").kind, ToolKind::printed);
}

TEST(SpaceTools, APlacedToolCarriesTheMapsPredictionRegion) {
  const SpaceTools tools = space_tools(space(), catalog(), catalog_file());
  const auto placed = std::find_if(tools.tools.begin(), tools.tools.end(),
                                   [](const SpaceTool& t) { return !t.judged; });
  ASSERT_NE(placed, tools.tools.end());
  EXPECT_EQ(placed->region_source, RegionSource::descriptor_map);
  // Recomputed here from the map: the list must be what placed_tools.png draws.
  const Placement p = place_from_descriptors(*space().descriptor_map, placed->descriptors);
  EXPECT_EQ(placed->position, p.mean);
  const PlaneEllipse e = plane_ellipse(gaussian_region(p.mean, p.covariance, {0.68, 0.95}), 0);
  EXPECT_DOUBLE_EQ(placed->ellipses[0].semi_axis_1, e.semi_axis_1);
  EXPECT_DOUBLE_EQ(placed->ellipses[0].angle_rad, e.angle_rad);
  bool commercial = false;
  for (const auto& t : tools.tools) commercial = commercial || t.kind == ToolKind::commercial;
  EXPECT_TRUE(commercial);
}

TEST(SpaceTools, WithoutBootstrapOrMapTheStimuliHaveNoRegionAndNothingIsPlaced) {
  SpaceFile bare = space();
  bare.regions.clear();
  bare.region_levels.clear();
  bare.descriptor_map.reset();
  const SpaceTools tools = space_tools(bare, catalog(), catalog_file());
  ASSERT_EQ(tools.tools.size(), 15u);
  for (const auto& t : tools.tools) {
    EXPECT_EQ(t.region_source, RegionSource::none);
    EXPECT_FALSE(t.region.has_value());
    EXPECT_TRUE(t.ellipses.empty());
  }
}

TEST(PlaceCatalog, EveryPairingInCatalogOrderJudgedOrNotAsTheMapPlacesIt) {
  const std::vector<PlacedPairing> placed = place_catalog(space(), catalog(), catalog_file());
  const DescriptorTable all = descriptors_of_catalog(catalog(), catalog_file(), 2);
  ASSERT_EQ(placed.size(), all.rows.size());
  std::size_t judged = 0;
  for (std::size_t i = 0; i < placed.size(); ++i) {
    EXPECT_EQ(placed[i].pairing, all.rows[i]);
    const bool stimulus = std::find(space().stimuli.begin(), space().stimuli.end(),
                                    placed[i].pairing) != space().stimuli.end();
    EXPECT_EQ(placed[i].judged, stimulus) << placed[i].pairing;
    judged += placed[i].judged ? 1 : 0;
    // The same arithmetic on the same numbers: exact.
    const Placement p = place_from_descriptors(*space().descriptor_map,
                                               all.values.row(static_cast<Eigen::Index>(i)).transpose());
    EXPECT_EQ(placed[i].placement.mean, p.mean) << placed[i].pairing;
    EXPECT_EQ(placed[i].placement.covariance, p.covariance) << placed[i].pairing;
  }
  EXPECT_EQ(judged, space().stimuli.size());
  // space_tools draws the same placements for the tools that were not judged.
  const SpaceTools tools = space_tools(space(), catalog(), catalog_file());
  for (const auto& p : placed)
    if (!p.judged) EXPECT_EQ(find(tools, p.pairing).position, p.placement.mean) << p.pairing;
}

TEST(PlaceCatalog, APredictedToolIsKnownByItsKindAndCarriesItsDescriptorError) {
  // A predicted tool as `nibrig predict` adds it to a catalog: kind "predicted", with the
  // descriptors of a measured pairing so that the two compare.
  io::Catalog with_prediction = catalog();
  const io::Pairing measured = *std::find_if(
      with_prediction.pairings.begin(), with_prediction.pairings.end(),
      [](const io::Pairing& p) { return p.friction && p.vibration; });
  io::ToolEntry entry;
  entry.id = "pred:vero:1,tip=2mm";
  entry.name = "predicted vero:1,tip=2mm";
  entry.kind = "predicted";
  with_prediction.tools.push_back(entry);
  io::Pairing pairing = measured;
  pairing.tool = entry.id;
  with_prediction.pairings.push_back(pairing);
  const std::string name = pairing_name(pairing);
  Eigen::MatrixXd error = Eigen::MatrixXd::Zero(2, 2);
  error(0, 0) = 0.01 * 0.01;
  error(1, 1) = 0.1 * 0.1;
  const std::vector<PlacedPairing> placed =
      place_catalog(space(), with_prediction, catalog_file(), {{name, error}});
  const auto at = [&](const std::string& n) {
    return *std::find_if(placed.begin(), placed.end(),
                         [&](const PlacedPairing& p) { return p.pairing == n; });
  };
  const PlacedPairing predicted = at(name), twin = at(pairing_name(measured));
  EXPECT_EQ(predicted.kind, ToolKind::predicted);
  EXPECT_NE(twin.kind, ToolKind::predicted);
  EXPECT_FALSE(predicted.judged);
  // Same descriptors, same mean; the descriptor error only widens the region, by the exact
  // J·Σ·Jᵀ the map adds (descriptor_map_test checks that term itself).
  EXPECT_EQ(predicted.placement.mean, twin.placement.mean);
  const Placement expected = place_from_descriptors(*space().descriptor_map, twin.descriptors, error);
  EXPECT_EQ(predicted.placement.covariance, expected.covariance);
  EXPECT_GT(predicted.placement.covariance.trace(), twin.placement.covariance.trace());
}

TEST(PlaceCatalog, RefusesASpaceWithoutADescriptorMap) {
  SpaceFile bare = space();
  bare.descriptor_map.reset();
  try {
    place_catalog(bare, catalog(), catalog_file());
    FAIL() << "placed tools without a map";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("no descriptor map"), std::string::npos) << e.what();
  }
}

TEST(SpaceTools, KindsFollowTheCatalogsWords) {
  EXPECT_EQ(tool_kind("commercial"), ToolKind::commercial);
  EXPECT_EQ(tool_kind("sharpie"), ToolKind::unknown);
  EXPECT_STREQ(kind_name(ToolKind::printed), "printed");
}

}  // namespace
}  // namespace nibrig::model::space
