// A space fitted from a judgments file as `nibrig space fit` and the panel's Fit make it: the
// fit_space optimum itself (the same starts and seed give the same coordinates to the bit), its
// descriptor map learnt from the catalog's descriptors, bootstrap regions at 68 and 95 %, the
// file's provenance; progress named by step; a cancel flag honoured; too few stimuli for a map
// said in a warning.
#include "model/space/space_fit_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "model/io/bundled_assets.hpp"
#include "model/numeric/cancellation.hpp"
#include "tests/model/space/study_fixture.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::space {
namespace {

using ::testing::HasSubstr;

// Every triplet of `stimuli` (catalog pairings on office paper) judged 8 times by an observer of
// a random 2-D space, written as our CSV.
std::filesystem::path judged(const std::vector<std::string>& stimuli, const std::string& name) {
  const auto truth = testing::random_truth(2, static_cast<Eigen::Index>(stimuli.size()), 11);
  io::TripletSet set;
  set.stimuli = stimuli;
  set.triplets = testing::every_triplet_judged(truth, 8, 12).triplets;
  const auto file = nibrig::test::scratch_dir(name) / "judgments.csv";
  io::write_triplet_csv(file, set);
  return file;
}

const std::vector<std::string> kEight = {"vero1/office", "vero2/office", "vero4/office", "DM851/office",
                                         "DM854/office", "DM951/office", "cryon/office", "stab/office"};

TEST(SpaceFitFile, HoldsTheFitItsDescriptorMapAndRegions) {
  const auto judgments = judged(kEight, "space_fit_file");
  const auto catalog = io::default_catalog();
  const auto in = read_space_inputs(judgments, catalog, 2, 1.0);
  SpaceFitSettings settings;
  settings.starts = 4;
  settings.seed = 3;
  settings.bootstrap = 20;
  std::vector<std::string> steps;
  std::size_t last_done = 0, last_total = 0;
  const auto fitted = fit_space_file(in, judgments, catalog, settings,
                                     [&](const std::string& step, std::size_t done, std::size_t total) {
                                       if (steps.empty() || steps.back() != step) steps.push_back(step);
                                       last_done = done, last_total = total;
                                     });
  // The optimum fit_space finds from the same starts (start k seeded seed + k, whatever the threads).
  FitOptions options;
  options.starts = 4;
  options.seed = 3;
  const auto reference = fit_space(in.problem, options);
  EXPECT_EQ(fitted.file.coordinates, reference.coordinates);
  EXPECT_EQ(fitted.file.stimuli, kEight);
  EXPECT_EQ(fitted.file.lambda, 1.0);
  EXPECT_EQ(fitted.file.judgments, judgments.string());
  EXPECT_EQ(fitted.file.descriptor_source, catalog.string());
  EXPECT_EQ(fitted.file.responses, io::response_count(in.judgments));
  EXPECT_EQ(fitted.file.start_objectives.size(), 4u);
  // Eight stimuli are enough for a map from two descriptors (and a constant) to each axis.
  ASSERT_TRUE(fitted.file.descriptor_map.has_value());
  const auto map = fit_descriptor_map(reference.coordinates, fitted.file.descriptors, fitted.file.descriptor_names);
  EXPECT_EQ(fitted.file.descriptor_map->coefficients, map.coefficients);
  EXPECT_TRUE(fitted.warnings.empty());
  ASSERT_EQ(fitted.file.regions.size(), kEight.size());
  EXPECT_EQ(fitted.file.region_levels, (std::vector<double>{0.68, 0.95}));
  EXPECT_EQ(fitted.file.bootstrap_resamples, 20);
  EXPECT_GT(fitted.mean_region_sd, 0.0);
  EXPECT_EQ(steps, (std::vector<std::string>{"fitting starts", "bootstrap refits"}));
  EXPECT_EQ(last_done, 20u);
  EXPECT_EQ(last_total, 20u);
}

TEST(SpaceFitFile, ACancelledFitThrowsCancelled) {
  const auto judgments = judged(kEight, "space_fit_file_cancel");
  const auto in = read_space_inputs(judgments, {}, 2, 0.0);
  std::stop_source cancel;
  cancel.request_stop();
  SpaceFitSettings settings;
  settings.stop = cancel.get_token();
  EXPECT_THROW(fit_space_file(in, judgments, {}, settings), numeric::Cancelled);
}

TEST(SpaceFitFile, TooFewStimuliForADescriptorMapAreSaidInAWarning) {
  const std::vector<std::string> three = {"cryon/office", "stab/office", "vero1/office"};
  const auto judgments = judged(three, "space_fit_file_three");
  const auto in = read_space_inputs(judgments, io::default_catalog(), 2, 1.0);
  SpaceFitSettings settings;
  settings.starts = 2;
  const auto fitted = fit_space_file(in, judgments, io::default_catalog(), settings);
  EXPECT_FALSE(fitted.file.descriptor_map.has_value());
  // Three stimuli in 2-D are too few for the fit itself too (fit_diagnostic.hpp): 3 triplets for
  // 2 × 2 free coordinates. Both are said.
  ASSERT_EQ(fitted.warnings.size(), 2u);
  EXPECT_THAT(fitted.warnings[0], HasSubstr("the fit is not identified: 3 judged triplets for 4 free coordinates"));
  EXPECT_THAT(fitted.warnings[1], HasSubstr("3 stimuli are too few"));
  EXPECT_TRUE(fitted.file.regions.empty());
}

}  // namespace
}  // namespace nibrig::model::space
