// What a space fit is asked for, checked before any judgment is read: each refusal names its field
// in the words of the face that asked (`--lambda` on the command line, `lam` in Python), so every
// face has the same bounds from here.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>

#include "model/space/dimension_scan.hpp"
#include "model/space/space_fit_file.hpp"

namespace nibrig::model::space {

inline constexpr std::size_t kMostSpaceDims = 10;
inline constexpr int kMostBootstrapResamples = 100000;
inline constexpr int kMostFolds = 100;

struct SpaceFitRequest {
  std::size_t dims = 2;
  double lambda = 0.0;
  std::filesystem::path descriptors;  // the catalog the axes may be tied to; empty: none
  SpaceFitSettings settings;
  // settings.candidates were listed by the person asking, not left at every family: only
  // settings.choose_model has candidates.
  bool candidates_listed = false;
};

class SpaceFitRefused : public std::invalid_argument {
 public:
  enum class Field {
    dims,         // outside 1..kMostSpaceDims
    lambda,       // outside [0, kMaxLambda]
    descriptors,  // none, with λ above 0
    starts,       // outside 1..kMostFitStarts
    bootstrap,    // 1, or above kMostBootstrapResamples (0: none)
    folds,        // outside 2..kMostFolds
    models,       // candidates listed without choosing the model
  };
  SpaceFitRefused(Field field, const std::string& what);
  Field field() const noexcept { return field_; }

 private:
  Field field_;
};
using SpaceFitField = SpaceFitRefused::Field;

// The Python arguments' names: "dims", "lam", "descriptors", "starts", "bootstrap", "folds",
// "models".
const char* field_name(SpaceFitField field);
using SpaceFitNames = std::function<std::string(SpaceFitField)>;

// Throws SpaceFitRefused, its message in `names`' words: "lam: 20000: expected a weight from 0 to
// 10000".
void check_space_fit(const SpaceFitRequest& request, const SpaceFitNames& names = field_name);

// The same bounds on a dimension scan's fits (space validate): every dims and λ, the folds and
// starts, and at least one model; `descriptors` empty when no catalog was given.
void check_dimension_scan(const DimensionScanOptions& scan,
                          const std::filesystem::path& descriptors, const SpaceFitNames& names);

}  // namespace nibrig::model::space
