#include "model/space/space_fit_request.hpp"

#include <fmt/format.h>

#include <cmath>

#include "model/space/fit.hpp"
#include "model/space/objective.hpp"

namespace nibrig::model::space {

namespace {

using Field = SpaceFitField;

[[noreturn]] void refuse(Field field, const SpaceFitNames& names, const std::string& why) {
  throw SpaceFitRefused(field, names(field) + ": " + why);
}

void whole_in_range(Field field, const SpaceFitNames& names, long long value, long long least,
                    long long most, const char* what) {
  if (value < least || value > most)
    refuse(field, names, fmt::format("{}: expected {}, {} to {}", value, what, least, most));
}

void check_lambda(Field field, const SpaceFitNames& names, double lambda,
                  const std::filesystem::path& descriptors) {
  if (!(lambda >= 0 && lambda <= kMaxLambda))
    refuse(field, names, fmt::format("{:g}: expected a weight from 0 to {:g}", lambda, kMaxLambda));
  if (lambda > 0 && descriptors.empty())
    refuse(Field::descriptors, names,
           fmt::format("none, with {} above 0: it ties the axes to the descriptors of a catalog",
                       names(field)));
}

}  // namespace

SpaceFitRefused::SpaceFitRefused(Field field, const std::string& what)
    : std::invalid_argument(what), field_(field) {}

const char* field_name(SpaceFitField field) {
  switch (field) {
    case Field::dims:
      return "dims";
    case Field::lambda:
      return "lam";
    case Field::descriptors:
      return "descriptors";
    case Field::starts:
      return "starts";
    case Field::bootstrap:
      return "bootstrap";
    case Field::folds:
      return "folds";
    case Field::models:
      return "models";
  }
  return "?";
}

void check_space_fit(const SpaceFitRequest& request, const SpaceFitNames& names) {
  const auto& s = request.settings;
  whole_in_range(Field::dims, names, static_cast<long long>(request.dims), 1,
                 static_cast<long long>(kMostSpaceDims), "a number of dimensions");
  check_lambda(Field::lambda, names, request.lambda, request.descriptors);
  whole_in_range(Field::starts, names, s.starts, 1, kMostFitStarts, "a number of starts");
  if (s.bootstrap != 0)
    whole_in_range(Field::bootstrap, names, s.bootstrap, 2, kMostBootstrapResamples,
                   "a number of resamples (0: none)");
  whole_in_range(Field::folds, names, s.folds, 2, kMostFolds, "a number of folds");
  if (request.candidates_listed && !s.choose_model)
    refuse(Field::models, names, "the candidates of a model chosen by cross-validation (auto)");
}

void check_dimension_scan(const DimensionScanOptions& scan,
                          const std::filesystem::path& descriptors, const SpaceFitNames& names) {
  if (scan.dims.empty()) refuse(Field::dims, names, "none: expected numbers of dimensions");
  for (const auto d : scan.dims)
    whole_in_range(Field::dims, names, static_cast<long long>(d), 1,
                   static_cast<long long>(kMostSpaceDims), "a number of dimensions");
  if (scan.lambdas.empty()) refuse(Field::lambda, names, "none: expected weights");
  for (const auto lambda : scan.lambdas) check_lambda(Field::lambda, names, lambda, descriptors);
  whole_in_range(Field::starts, names, scan.cross_validation.fit.starts, 1, kMostFitStarts,
                 "a number of starts");
  whole_in_range(Field::folds, names, scan.cross_validation.folds, 2, kMostFolds,
                 "a number of folds");
  if (scan.models.empty()) refuse(Field::models, names, "none: expected judgment models");
}

}  // namespace nibrig::model::space
