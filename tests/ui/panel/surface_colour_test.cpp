// A surface's colour is a function of its name: the same in every space, whatever order the
// space lists its stimuli in (glass had been pink in one space and green in another), and the
// bundled catalog's surfaces each have one of their own.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "model/io/bundled_assets.hpp"
#include "model/io/catalog_file.hpp"
#include "tests/ui/panel/test_space.hpp"
#include "ui/panel/space_scene.hpp"

namespace nibrig::ui::panel {
namespace {

TEST(SurfaceColour, ASurfacesColourIsTheSameInEverySpaceAndTheBundledOnesDiffer) {
  const auto dir = nibrig::test::scratch_dir("panel_surface_colour");
  model::space::SpaceFile forward = testing::small_space();
  model::space::SpaceFile reversed = forward;
  std::reverse(reversed.stimuli.begin(), reversed.stimuli.end());
  reversed.coordinates = forward.coordinates.rowwise().reverse().eval();
  model::space::write_space_file(dir / "forward.json", forward);
  model::space::write_space_file(dir / "reversed.json", reversed);
  const SpaceScene a = load_space_file(dir / "forward.json", {}).scene;
  const SpaceScene b = load_space_file(dir / "reversed.json", {}).scene;
  ASSERT_EQ(a.surfaces.size(), 3u);
  ASSERT_EQ(b.surfaces.size(), 3u);
  ASSERT_NE(a.surfaces, b.surfaces) << "the two spaces list their surfaces in the same order";
  SpaceView view_a(a, {}), view_b(b, {});
  std::set<ImU32> colours;
  for (const std::string& surface : a.surfaces) {
    EXPECT_EQ(view_a.surface_colour(surface, 255), view_b.surface_colour(surface, 255)) << surface;
    colours.insert(view_a.surface_colour(surface, 255));
  }
  EXPECT_EQ(colours.size(), 3u) << "two surfaces of one space share a colour";

  // Every surface of the bundled catalog has a slot of its own (there are fewer than colours).
  const auto catalog = model::io::read_catalog(model::io::or_default({}, model::io::default_catalog));
  ASSERT_LE(catalog.surfaces.size(), kSurfaceSlots);
  SpaceScene all;
  for (const auto& s : catalog.surfaces) all.surfaces.push_back(s.id);
  const SpaceScene placed = load_space_file(dir / "forward.json", {}).scene;  // slots come with a scene
  std::set<std::size_t> slots(placed.surface_slots.begin(), placed.surface_slots.end());
  for (std::size_t i = 0; i < placed.surfaces.size(); ++i) {
    const auto at = std::find(all.surfaces.begin(), all.surfaces.end(), placed.surfaces[i]);
    ASSERT_NE(at, all.surfaces.end()) << placed.surfaces[i];
    EXPECT_EQ(placed.surface_slots[i], static_cast<std::size_t>(at - all.surfaces.begin())) << placed.surfaces[i];
  }
  EXPECT_EQ(slots.size(), placed.surfaces.size());
}

}  // namespace
}  // namespace nibrig::ui::panel
