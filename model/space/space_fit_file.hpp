// A space fitted from judgments, as its file holds it: the fit, its statistics, the descriptor map
// when the judged stimuli have descriptors and are enough to learn it, and on request bootstrap
// regions. One call for every face that fits a space, with progress
// named by step and a stop token that both the fit and the bootstrap honour.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "model/numeric/cancellation.hpp"
#include "model/space/bootstrap.hpp"
#include "model/space/fit.hpp"
#include "model/space/space_file.hpp"
#include "model/space/space_inputs.hpp"

namespace nibrig::model::space {

struct SpaceFitSettings {
  int starts = 16;
  unsigned seed = 1;
  unsigned threads = 0;  // 0: one per core
  int bootstrap = 0;     // resamples; 0: no confidence regions
  // The judgment model fitted, or, with choose_model, the one of `candidates` that predicts held-out
  // judgments best (model_choice.hpp: `folds`-fold cross-validation, `choice_starts` starts a fold).
  ModelFamily model = kPaperModel;
  bool choose_model = false;
  std::vector<ModelFamily> candidates = every_family();
  int folds = 5;
  int choice_starts = 2;
  std::stop_token stop;
};

// Called as each start or refit finishes: the step (kChoiceStep, kFitStep, then kBootstrapStep), how many of it
// are done, of how many. From worker threads, never two at once.
inline constexpr const char* kChoiceStep = "choosing the judgment model (fold fits)";
inline constexpr const char* kFitStep = "fitting starts";
inline constexpr const char* kBootstrapStep = "bootstrap refits";
using StepProgress =
    std::function<void(const std::string& step, std::size_t done, std::size_t total)>;

struct FittedSpace {
  SpaceFile file;
  FitResult fit;
  double bootstrap_seconds = 0.0;
  double mean_region_sd = 0.0;        // mean per-axis sd of a stimulus (bootstrap), 0 without it
  std::vector<std::string> warnings;  // e.g. too few stimuli for a descriptor map
};

// Fits `in` (read by read_space_inputs from `judgments` and, when not empty, `descriptors`). Throws
// what fit_space and bootstrap_space throw (numeric::Cancelled when cancelled).
FittedSpace fit_space_file(const SpaceInputs& in, const std::filesystem::path& judgments,
                           const std::filesystem::path& descriptors,
                           const SpaceFitSettings& settings, const StepProgress& progress = {});

}  // namespace nibrig::model::space
