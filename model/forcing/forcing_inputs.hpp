// What fitting the forcing model starts from, read from files once: the catalog's printed-tool
// exemplars with the simulated response of each tool's design, and the notes that say where
// everything came from. Shared by every face that fits (`forcing fit`, `loo`, `holdout`, the
// on-the-fly fit of predict and design, the demo).
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "model/forcing/catalog_exemplars.hpp"
#include "model/forcing/forcing_model.hpp"
#include "model/forcing/leave_one_out.hpp"

namespace nibrig::model::forcing {

struct ForcingInputOptions {
  std::filesystem::path catalog;          // empty: the bundled default catalog
  std::filesystem::path design_template;  // empty: assets/designs/stylus_vero_tip2mm.json
  std::filesystem::path materials;        // empty: assets/materials.json
  int modes = 0;                          // 0: the template's
  double mesh_size = 0.0;                 // m; 0: the template's
  // Empty: each exemplar's spectrum as the catalog holds it. Else every spectrum is put on these
  // frequencies (io::spectrum_at_frequencies) before its response is computed: a calibration takes
  // a lab's recordings, whatever their resolution, on its model's grid.
  std::vector<double> frequencies_hz;
};

// The ranges every face holds these options to (the command line's check the same numbers): at
// most kMostModes modes, and an element size at most 1 m (every stylus dimension is centimetres;
// metres typed for millimetres is the usual slip). 0 is the template's, for both.
inline constexpr int kMostModes = 1000;
inline constexpr double kLargestMeshSizeM = 1.0;

// Throws std::invalid_argument "modes: ..." or "mesh_size: ..." (a Python call's names) for a value
// outside those ranges or not finite. load_forcing_inputs and load_prediction_inputs call it first.
void check_forcing_input_options(const ForcingInputOptions& options);

struct ForcingInputs {
  std::vector<ForcingExemplar> exemplars;
  ExemplarSelection selection;  // its exemplars moved to `exemplars`
  std::vector<DesignResponse> designs;
  double response_seconds = 0.0;
  std::vector<std::string> notes;  // provenance and assumptions, for forcing.json and the summary
};

// Called as each distinct design has been meshed and solved (done of total), for progress.
using DesignProgress =
    std::function<void(const DesignResponse&, std::size_t done, std::size_t total)>;

// Reads the catalog first (so a bad catalog fails before any meshing), then the materials and the
// template, then meshes and solves each distinct design once. Throws std::runtime_error naming a
// missing file and what it should have been, or a catalog with nothing to fit.
ForcingInputs load_forcing_inputs(const ForcingInputOptions& options,
                                  const DesignProgress& progress = {});

// The model every face fits: Eq. 10 fitted to every exemplar, with the inputs' notes and the
// descriptor errors of every exemplar held out in turn (weighted by the bundled threshold curve),
// which predicted tools' placements carry. The leave-one-out fits take about twice as long as the
// fit itself; they are returned too (results[k] holds out exemplars[k]), so a summary of any
// subset costs no refit.
struct ForcingForPrediction {
  ForcingModel model;
  LeaveOneOut every_exemplar_held_out;
};
ForcingForPrediction fit_forcing_for_prediction(const ForcingInputs& inputs);

// Lines a person reads first: exemplars, what was left out, the paper's tools present and missing,
// the designs simulated.
std::string describe_inputs(const ForcingInputs& inputs);

}  // namespace nibrig::model::forcing
