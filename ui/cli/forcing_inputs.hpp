// What `nibrig forcing fit` and `forcing loo` share: the catalog's printed-tool exemplars with the
// simulated response of each tool's design, and the notes that say where everything came from.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "model/forcing/catalog_exemplars.hpp"
#include "model/forcing/forcing_model.hpp"
#include "model/forcing/leave_one_out.hpp"

namespace CLI {
class App;
}

namespace nibrig::ui::cli {

struct ForcingInputOptions {
  std::filesystem::path catalog;          // empty: the bundled default catalog
  std::filesystem::path design_template;  // empty: assets/designs/stylus_vero_tip2mm.json
  std::filesystem::path materials;        // empty: assets/materials.json
  int modes = 0;                          // 0: the template's
  double mesh_size = 0.0;                 // m; 0: the template's
};

struct ForcingInputs {
  std::vector<model::forcing::ForcingExemplar> exemplars;
  model::forcing::ExemplarSelection selection;  // its exemplars moved to `exemplars`
  std::vector<model::forcing::DesignResponse> designs;
  double response_seconds = 0.0;
  std::vector<std::string> notes;  // provenance and assumptions, for forcing.json and the summary
};

// Reads the catalog first (so a bad catalog fails before any meshing), then the materials and the
// template, then meshes and solves each distinct design once, with progress on a terminal.
ForcingInputs load_forcing_inputs(const ForcingInputOptions& options);

// The model every command fits (forcing fit, the on-the-fly fit of predict and design, the demo):
// Eq. 10 fitted to every exemplar, with the inputs' notes and the descriptor errors of every
// exemplar held out in turn (weighted by the bundled threshold curve), which predicted tools'
// placements carry. The leave-one-out fits take about twice as long as the fit itself; they are
// returned too (results[k] holds out exemplars[k]), so a summary of any subset costs no refit.
struct ForcingForPrediction {
  model::forcing::ForcingModel model;
  model::forcing::LeaveOneOut every_exemplar_held_out;
};
ForcingForPrediction fit_forcing_for_prediction(const ForcingInputs& inputs);

// The options above on a command: the catalog as a positional argument, --design, --materials,
// --modes and --mesh-size. Files are checked when read, so a bad one fails in one line.
void add_forcing_input_options(CLI::App* cmd, ForcingInputOptions& o);

// Lines a person reads first: exemplars, what was left out, the paper's tools present and missing,
// the designs simulated.
std::string describe_inputs(const ForcingInputs& inputs);

}  // namespace nibrig::ui::cli
