// A fitted forcing model on disk (forcing.json, format "nibrig-forcing" version 1): what
// `nibrig forcing fit` writes and prediction reads. Layout in FORMATS.md, "Forcing model".
#pragma once

#include <filesystem>
#include <string>

#include "model/forcing/forcing_model.hpp"

namespace nibrig::model::forcing {

// {"format": "nibrig-forcing", "version": 1, "knot_frequencies_hz": [...],
//  "reference": {"tip_diameter_mm", "material"},
//  "tip_curves": [{"tip_diameter_mm", "log_gain": [one per knot]}],
//  "material_curves": [{"material", "log_gain": [...], "log_gain_se": [optional, per knot]}],
//  "frequencies_hz": [...], "speeds_mm_s": [...],
//  "surfaces": [{"id", "forcing_n": [[one per frequency] per speed],
//                "log_forcing_se": [optional, shaped like forcing_n]}],
//  "fit": {"residual_rms_db", "observations", "skipped_nonpositive",
//          "exemplars": [{"tool", "surface", "rms_db"}]},
//  "held_out_descriptor_errors": {"threshold_curve", "exemplars": [{"tool", "surface",
//          "log10_weighted_mean", "log10_band_energies": {"2": [2 values], …, "5": [5 values]}}]},
//  "notes": [...]}
// log_gain is the natural log of the gain; log_gain_se and log_forcing_se, the standard errors of
// a material or surface calibrated from a few prints (forcing_model.hpp), are optional, and a file
// without them reads as before. held_out_descriptor_errors is optional (files written
// before it existed lack it; the model's vector is then empty). Written through a temporary file
// and a rename.
void write_forcing_model(const std::filesystem::path& file, const ForcingModel& model);

// Throws io::FormatError naming the file and field: wrong format or version, a missing field,
// knots or frequencies not strictly increasing, frequencies outside the knots, a curve or forcing
// row of the wrong length, duplicate tips, materials or surfaces, a reference without its curve or
// with a non-zero one (the gauge), negative or non-finite numbers where they cannot be, a
// descriptor error without every band count from 2 to 5 or with the wrong number of bands.
ForcingModel read_forcing_model(const std::filesystem::path& file);

// The file's text and its reading from text, for a model kept in memory (a pickled designer's):
// the same checks, `file` naming the text in errors. Doubles keep every digit; the diameters and
// speeds, written in mm, come back to within a unit in the last place.
std::string forcing_model_text(const ForcingModel& model, const std::filesystem::path& file);
ForcingModel parse_forcing_model(const std::string& text, const std::filesystem::path& file);

}  // namespace nibrig::model::forcing
