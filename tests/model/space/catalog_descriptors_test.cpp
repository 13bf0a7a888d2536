#include "model/space/catalog_descriptors.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "model/io/format_error.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::space {
namespace {

const std::filesystem::path& catalog_file() {
  static const std::filesystem::path f = nibrig::test::assets_dir() / "default_catalog.json";
  return f;
}

const io::Pairing& pairing(const io::Catalog& c, const std::string& tool,
                           const std::string& surface) {
  for (const auto& p : c.pairings)
    if (p.tool == tool && p.surface == surface) return p;
  throw std::runtime_error("no pairing " + tool + "/" + surface);
}

TEST(SpaceCatalogDescriptors, RowsFollowTheStimuliAndSectionFourFive) {
  const io::Catalog c = io::read_catalog(catalog_file());
  const DescriptorTable t =
      descriptors_for_stimuli(c, catalog_file(), {"cryon/office", "stab/stone"}, 2);
  ASSERT_EQ(t.values.rows(), 2);
  EXPECT_EQ(t.names, (std::vector<std::string>{"friction_mu", "log10_weighted_mean_vibration"}));
  const io::Pairing& p = pairing(c, "stab", "stone");
  EXPECT_DOUBLE_EQ(t.values(1, 0), p.friction->mu);
  EXPECT_DOUBLE_EQ(t.values(1, 1), std::log10(p.vibration->weighted_mean));
  // Three axes: μ and the two band energies of the 2-band split.
  const DescriptorTable three = descriptors_for_stimuli(c, catalog_file(), {"stab/stone"}, 3);
  EXPECT_DOUBLE_EQ(three.values(0, 2), std::log10(p.vibration->band_energies.at(2)[1]));
}

TEST(SpaceCatalogDescriptors, AStimulusWithoutAPairingIsNamed) {
  const io::Catalog c = io::read_catalog(catalog_file());
  try {
    descriptors_for_stimuli(c, catalog_file(), {"cryon/office", "unicorn/office"}, 2);
    FAIL() << "an unknown stimulus was accepted";
  } catch (const io::FormatError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("unicorn/office"), std::string::npos) << what;
    EXPECT_NE(what.find("default_catalog.json"), std::string::npos) << what;
  }
  EXPECT_THROW(paper_descriptor_names(7), std::invalid_argument);
}

TEST(SpaceCatalogDescriptors, AllNamesAreEveryDimensionsNamesOnce) {
  const auto all = all_paper_descriptor_names();
  // μ, the weighted mean, and 2 + 3 + 4 + 5 band energies.
  EXPECT_EQ(all.size(), 1u + 1u + 14u);
  for (std::size_t dims = 1; dims <= 6; ++dims)
    for (const auto& name : paper_descriptor_names(dims))
      EXPECT_EQ(std::count(all.begin(), all.end(), name), 1) << name;
}

TEST(SpaceCatalogDescriptors, TheWholeCatalogHasEveryCompletePairing) {
  const io::Catalog c = io::read_catalog(catalog_file());
  std::size_t complete = 0;
  for (const auto& p : c.pairings) complete += p.friction && p.vibration;
  EXPECT_EQ(static_cast<std::size_t>(descriptors_of_catalog(c, catalog_file(), 2).values.rows()),
            complete);
}

}  // namespace
}  // namespace nibrig::model::space
