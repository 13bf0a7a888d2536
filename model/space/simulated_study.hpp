// The perceptual space the faces start from while no human judgments of drawing
// tools are bundled: an observer whose perception is the catalog's descriptors answers the paper's
// two-stage triplet experiment (Sec. 4.3) on 15 tool/surface pairs, and the answers are fitted
// with bootstrap regions and a descriptor map, as a real study would be. Deterministic in its seed.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "model/io/catalog_file.hpp"
#include "model/io/triplets.hpp"
#include "model/numeric/cancellation.hpp"
#include "model/numeric/progress_counter.hpp"
#include "model/space/bootstrap.hpp"
#include "model/space/catalog_descriptors.hpp"
#include "model/space/dimension_scan.hpp"
#include "model/space/fit.hpp"
#include "model/space/space_file.hpp"
#include "model/space/trial_plan.hpp"

namespace nibrig::model::space {

// Five tools on the paper's three papers, like the paper's 15 stimuli (Sec. 4.3). The paper's own
// five (pen, fineliner, pencils, charcoal) have no vibration recording in the shared data, so the
// two real tools that have one (crayon, Stabilo) join three printed nibs.
std::vector<std::string> demo_study_stimuli();

// Every number that shapes the result is here, so that a cache can key on all of them
// (model/design/default_space.hpp); the defaults are the demo's.
struct SimulatedStudyOptions {
  std::vector<std::string> stimuli = demo_study_stimuli();
  std::size_t dims = 2;
  double lambda = 1.0;
  std::uint64_t observer_seed = 2018;  // the observer's answers, both stages from one generator
  // Stage 1: half of the triplets, twice each; stage 2: up to 60 of its ties ten times (the
  // paper's sizes, 1366 + 600 trials for 15 stimuli).
  double stage_one_fraction = 0.5;
  int stage_one_repetitions = 2;
  std::uint64_t stage_one_plan_seed = 1;
  int stage_two_repetitions = 10;
  std::uint64_t stage_two_plan_seed = 2;
  std::size_t stage_two_triplets = 60;
  int bootstrap_resamples = 200;  // the paper used 1000; 200 keeps the demo quick

  // Not part of the result: which file the caller writes the judgments to, named in the space
  // file's provenance (empty: "not written").
  std::string judgments_file;
  unsigned threads = 0;  // 0: one per core; results do not depend on it
  // Steps "space fit starts" then "bootstrap refits".
  numeric::StepProgress progress;
  // Checked between the stages and before every fit start and refit; throws numeric::Cancelled.
  std::stop_token stop;
};

struct SimulatedStudy {
  DescriptorTable descriptors;  // stimuli × the space's descriptors
  Eigen::MatrixXd truth;        // the observer's space (dims × stimuli)
  TrialList stage_one, stage_two;
  std::size_t ties = 0;  // stage-one ties, before stage two's cap
  // Every answer of both stages, merged: the paper's selection (drop stage-1 ties) stretches the
  // space about 1.5× in `nibrig space synth`.
  io::TripletSet judgments;
  SpaceProblem problem;
  FitResult fit;
  BootstrapResult bootstrap;
  // The fit, its descriptor map and bootstrap regions as `nibrig space fit` would write them.
  SpaceFile space;
};

// Throws io::FormatError naming `catalog_file` and the stimulus for a stimulus the catalog lacks
// (or lacks descriptors for), what fit_space and bootstrap_space throw, numeric::Cancelled.
// The catalog's descriptors are used as they are: a caller that recomputes them (with another
// threshold curve) does so first.
SimulatedStudy run_simulated_study(const io::Catalog& catalog,
                                   const std::filesystem::path& catalog_file,
                                   const SimulatedStudyOptions& options = {});

// The demo's Fig. 8 for the study: 5-fold cross-validated error of 1-3 dimensions at λ = 0 and the
// study's λ (4 starts per fold), the axes tied to the paper's descriptors of each dimensionality.
// A separate call: the space does not depend on it and it takes as long as the study. Reports the
// step "cross-validation folds" and honours the stop token of `options`.
std::vector<DimensionScanPoint> scan_simulated_study(const SimulatedStudy& study,
                                                     const io::Catalog& catalog,
                                                     const std::filesystem::path& catalog_file,
                                                     const SimulatedStudyOptions& options = {});

}  // namespace nibrig::model::space
