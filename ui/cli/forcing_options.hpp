// How a command takes the inputs of the forcing fit (model/forcing/forcing_inputs.hpp) on its
// command line, and shows the designs being simulated as progress on a terminal.
#pragma once

#include "model/design/prediction_inputs.hpp"
#include "model/forcing/forcing_inputs.hpp"

namespace CLI {
class App;
}

namespace nibrig::ui::cli {

using model::design::load_prediction_inputs;
using model::design::PredictionInputs;
using model::forcing::describe_inputs;
using model::forcing::fit_forcing_for_prediction;
using model::forcing::ForcingForPrediction;
using model::forcing::ForcingInputOptions;
using model::forcing::ForcingInputs;
using model::forcing::load_forcing_inputs;

// The options on a command: the catalog as a positional argument, --design, --materials,
// --modes and --mesh-size. Files are checked when read, so a bad one fails in one line.
void add_forcing_input_options(CLI::App* cmd, ForcingInputOptions& o);

// A progress bar "simulating designs" on stderr (terminal only), drawn as designs finish.
model::forcing::DesignProgress design_progress();

}  // namespace nibrig::ui::cli
