// The work of `nibrig space fit|validate|predict|evaluate|embed` (registered in cmd_space.cpp).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "model/space/space_fit_request.hpp"

namespace nibrig::ui::cli {

struct SpaceFitOptions {
  std::filesystem::path judgments, descriptors, output = "space.json", plot;
  std::size_t dims = 2;
  double lambda = 0.0;
  int starts = 16;
  unsigned seed = 1;
  int bootstrap = 0;  // resamples; 0 = no confidence regions
  std::string model = "probit";     // a family's name, or "auto"
  std::vector<std::string> models;  // the candidates of --model auto; empty: every family
  int folds = 5;                    // of --model auto
};
void run_space_fit(const SpaceFitOptions& options, unsigned threads);
// A space fit's fields as `space fit`'s options, for the library's refusals.
std::string space_fit_option(model::space::SpaceFitField field);

struct SpaceValidateOptions {
  std::filesystem::path judgments, descriptors, output, plots;
  int folds = 5;
  std::vector<std::size_t> dims{1, 2, 3};
  std::vector<double> lambdas{0.0};
  std::vector<std::string> models{"probit"};  // family names, or "all"
  int starts = 8;
  unsigned seed = 1;
};
void run_space_validate(const SpaceValidateOptions& options, unsigned threads);

struct SpaceQueryOptions {
  std::filesystem::path space_file, queries, catalog, output;
};
// predict: p_first per query as CSV; evaluate: the predictions scored against the queries' own
// answers (Sec. 6.1).
void run_space_predict(const SpaceQueryOptions& options);
void run_space_evaluate(const SpaceQueryOptions& options);

struct SpaceEmbedOptions {
  std::filesystem::path space_file, catalog, output, plot;
  std::vector<std::filesystem::path> predicted;  // `nibrig predict` outputs placed beside the catalog
};
void run_space_embed(const SpaceEmbedOptions& options);

}  // namespace nibrig::ui::cli

namespace nibrig::ui::cli {

struct SpaceSynthOptions {
  std::vector<std::size_t> dims{1, 2, 3, 4, 5};
  std::size_t trials = 100, stimuli = 15;
  int starts = 4;
  unsigned seed = 1;
  bool all_judgments = false;  // fit every answer instead of the paper's selection
  bool compare = false;        // adaptive vs two-stage at several budgets
  std::vector<std::size_t> budgets{500, 1000, 1966};
  std::size_t compare_trials = 20;
  std::filesystem::path output, plots;
};
void run_space_synth(const SpaceSynthOptions& options, unsigned threads);

struct SpacePlanOptions {
  std::filesystem::path input, output;  // stage 1: stimulus list; stage 2: answered stage-1 list
  int stage = 1;
  int repetitions = 0;  // 0: the paper's (2 in stage 1, 10 in stage 2)
  double fraction = 0.5;
  std::size_t max_triplets = 60;
  unsigned seed = 1;
};
void run_space_plan(const SpacePlanOptions& options);

struct SpaceMergeOptions {
  std::vector<std::filesystem::path> lists;  // answered trial lists (stage 1, then stage 2)
  std::filesystem::path output;
  bool all_judgments = false;
};
void run_space_merge(const SpaceMergeOptions& options);

}  // namespace nibrig::ui::cli
