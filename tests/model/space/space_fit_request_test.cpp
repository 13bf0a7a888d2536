// A space fit's and a dimension scan's bounds: each refusal carries its field and names it in the
// words the face gave, and a request inside every bound passes.
#include "model/space/space_fit_request.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace nibrig::model::space {
namespace {

using Field = SpaceFitField;

// The field a check refused and its message; a check that passed gives nullopt.
std::optional<std::pair<Field, std::string>> refusal(const std::function<void()>& check) {
  try {
    check();
  } catch (const SpaceFitRefused& e) {
    return std::pair(e.field(), std::string(e.what()));
  }
  return std::nullopt;
}

std::string option(Field field) { return "--" + std::string(field_name(field)); }

TEST(SpaceFitRequest, EachBoundIsRefusedAsItsFieldInTheFacesWords) {
  const auto refused = [](const std::function<void(SpaceFitRequest&)>& change) {
    SpaceFitRequest r;
    change(r);
    return refusal([&] { check_space_fit(r, option); });
  };
  EXPECT_EQ(refused([](SpaceFitRequest&) {}), std::nullopt);
  EXPECT_EQ(refused([](SpaceFitRequest& r) {
              r.lambda = kMaxLambda, r.descriptors = "catalog.json", r.dims = kMostSpaceDims;
              r.settings.bootstrap = kMostBootstrapResamples, r.settings.folds = kMostFolds;
              r.settings.starts = kMostFitStarts;
              r.settings.choose_model = true, r.candidates_listed = true;
            }),
            std::nullopt);
  const std::vector<std::pair<std::function<void(SpaceFitRequest&)>, std::pair<Field, std::string>>>
      cases = {
          {[](auto& r) { r.dims = 0; },
           {Field::dims, "--dims: 0: expected a number of dimensions, 1 to 10"}},
          {[](auto& r) { r.dims = 11; },
           {Field::dims, "--dims: 11: expected a number of dimensions, 1 to 10"}},
          {[](auto& r) { r.lambda = -1; },
           {Field::lambda, "--lam: -1: expected a weight from 0 to 10000"}},
          {[](auto& r) { r.lambda = std::nan(""), r.descriptors = "c.json"; },
           {Field::lambda, "--lam: nan: expected a weight from 0 to 10000"}},
          {[](auto& r) { r.lambda = 0.5; },
           {Field::descriptors,
            "--descriptors: none, with --lam above 0: it ties the axes to the descriptors of a "
            "catalog"}},
          {[](auto& r) { r.settings.starts = 0; },
           {Field::starts, "--starts: 0: expected a number of starts, 1 to 10000"}},
          {[](auto& r) { r.settings.bootstrap = 1; },
           {Field::bootstrap,
            "--bootstrap: 1: expected a number of resamples (0: none), 2 to 100000"}},
          {[](auto& r) { r.settings.bootstrap = -2; },
           {Field::bootstrap,
            "--bootstrap: -2: expected a number of resamples (0: none), 2 to 100000"}},
          {[](auto& r) { r.settings.folds = 1; },
           {Field::folds, "--folds: 1: expected a number of folds, 2 to 100"}},
          {[](auto& r) { r.candidates_listed = true; },
           {Field::models,
            "--models: the candidates of a model chosen by cross-validation (auto)"}},
      };
  for (const auto& [change, expected] : cases) EXPECT_EQ(refused(change), expected);
}

TEST(SpaceFitRequest, TheDefaultNamesArePythonsArguments) {
  SpaceFitRequest r;
  r.lambda = 2e4, r.descriptors = "catalog.json";
  EXPECT_EQ(refusal([&] { check_space_fit(r); }),
            std::pair(Field::lambda, std::string("lam: 20000: expected a weight from 0 to 10000")));
}

TEST(SpaceFitRequest, AScanIsHeldToTheSameBoundsForEveryPoint) {
  const auto refused = [](const std::function<void(DimensionScanOptions&)>& change,
                          const std::filesystem::path& catalog = {}) {
    DimensionScanOptions scan;
    change(scan);
    return refusal([&] { check_dimension_scan(scan, catalog, option); });
  };
  EXPECT_EQ(refused([](DimensionScanOptions&) {}), std::nullopt);
  EXPECT_EQ(refused([](auto& s) { s.lambdas = {0.0, 1.0}; }, "catalog.json"), std::nullopt);
  EXPECT_EQ(
      refused([](auto& s) {
        s.dims = {1, 2, 11};
      }),
      std::pair(Field::dims, std::string("--dims: 11: expected a number of dimensions, 1 to 10")));
  EXPECT_EQ(refused([](auto& s) { s.dims.clear(); })->first, Field::dims);
  EXPECT_EQ(refused([](auto& s) { s.lambdas = {0.0, 1.0}; })->first, Field::descriptors);
  EXPECT_EQ(refused([](auto& s) { s.lambdas = {-0.5}; }, "c.json")->first, Field::lambda);
  EXPECT_EQ(refused([](auto& s) { s.lambdas.clear(); })->first, Field::lambda);
  EXPECT_EQ(refused([](auto& s) { s.cross_validation.folds = 101; })->first, Field::folds);
  EXPECT_EQ(refused([](auto& s) { s.cross_validation.fit.starts = 0; })->first, Field::starts);
  EXPECT_EQ(refused([](auto& s) { s.models.clear(); })->first, Field::models);
}

}  // namespace
}  // namespace nibrig::model::space
