// Catalogs put together: the bundled one and a lab's, every entry kept once, and what the lab must
// choose (a tool described two ways, one pairing measured twice) refused naming both catalogs.
#include "model/catalog/merge.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "model/catalog/tool_names.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::catalog {
namespace {

using ::testing::HasSubstr;

io::Catalog lab_catalog() {
  io::Catalog c;
  c.tools = {describe_tool("lab-pla-1mm"), describe_tool("cryon")};
  c.surfaces = {describe_surface("office"), describe_surface("glass")};
  io::Pairing p;
  p.tool = "lab-pla-1mm", p.surface = "office";
  p.friction = io::FrictionDescriptor{};
  p.friction->mu = 0.21;
  c.pairings = {p};
  c.notes = {"captured on the lab's rig"};
  return c;
}

std::string refusal(const std::vector<NamedCatalog>& catalogs) {
  try {
    merge_catalogs(catalogs);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(MergeCatalogs, TheBundledAndALabsAreOneCatalogWithEveryEntryOnce) {
  const auto bundled = io::read_catalog(nibrig::test::assets_dir() / "default_catalog.json");
  const io::Catalog merged = merge_catalogs({{"bundled", bundled}, {"lab.json", lab_catalog()}});
  // The lab's print is new; its crayon and office paper are the bundled ones, kept once.
  EXPECT_EQ(merged.tools.size(), bundled.tools.size() + 1);
  EXPECT_EQ(merged.surfaces.size(), bundled.surfaces.size());
  EXPECT_EQ(merged.pairings.size(), bundled.pairings.size() + 1);
  EXPECT_EQ(merged.pairings.back().tool, "lab-pla-1mm");
  EXPECT_DOUBLE_EQ(merged.pairings.back().friction->mu, 0.21);
  EXPECT_EQ(merged.notes.back(), "lab.json: captured on the lab's rig");
  EXPECT_EQ(merged.citation, bundled.citation);
}

TEST(MergeCatalogs, WhatTheLabMustChooseIsRefusedNamingBothCatalogs) {
  io::Catalog twice = lab_catalog();
  EXPECT_THAT(refusal({{"a.json", lab_catalog()}, {"b.json", twice}}),
              HasSubstr("lab-pla-1mm on office is measured in both a.json and b.json"));
  io::Catalog renamed = lab_catalog();
  renamed.pairings.clear();
  renamed.tools[0].tip_diameter_m = 0.002;
  EXPECT_THAT(refusal({{"a.json", lab_catalog()}, {"b.json", renamed}}),
              HasSubstr("tool 'lab-pla-1mm' is described differently in a.json and b.json"));
  io::Catalog paper = lab_catalog();
  paper.pairings.clear();
  paper.surfaces[0].name = "A4 copier paper";
  EXPECT_THAT(refusal({{"a.json", lab_catalog()}, {"b.json", paper}}), HasSubstr("surface 'office'"));
}

}  // namespace
}  // namespace nibrig::model::catalog
