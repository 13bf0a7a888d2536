// The work of `nibrig space fit|validate|predict|evaluate|embed` (registered in cmd_space.cpp).
#pragma once

#include <filesystem>
#include <vector>

namespace nibrig::ui::cli {

struct SpaceFitOptions {
  std::filesystem::path judgments, descriptors, output = "space.json", plot;
  std::size_t dims = 2;
  double lambda = 0.0;
  int starts = 16;
  unsigned seed = 1;
  int bootstrap = 0;  // resamples; 0 = no confidence regions
};
void run_space_fit(const SpaceFitOptions& options, unsigned threads);

struct SpaceValidateOptions {
  std::filesystem::path judgments, descriptors, json, report;
  int folds = 5;
  std::vector<std::size_t> dims{1, 2, 3};
  std::vector<double> lambdas{0.0};
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
};
void run_space_embed(const SpaceEmbedOptions& options);

}  // namespace nibrig::ui::cli
