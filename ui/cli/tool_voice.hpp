// How the CLI turns "tool X on surface Y" into a real-time voice: the catalog's acceleration
// spectrum of that pairing, shaped by a stylus's modes (by default the bundled printed stylus with
// a 2 mm tip), built at the engine's internal rate. Shared by render, audition and the demo.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "model/design/predicted_tool.hpp"
#include "model/io/catalog_file.hpp"
#include "model/modal/modal_model.hpp"
#include "rt/voice.hpp"

namespace nibrig::ui::cli {

// The stylus whose modes every voice gets unless the user names another design.
inline constexpr const char* kDefaultVoiceDesign = "designs/stylus_vero_tip2mm.json";

struct StylusModes {
  std::string name;
  model::modal::ModalModel modal;
};

// Meshes the design (a nibrig-design JSON; empty = kDefaultVoiceDesign) and solves for its modes.
StylusModes stylus_modes(const std::filesystem::path& design);

// The catalog (empty = the bundled default).
model::io::Catalog voice_catalog(const std::filesystem::path& catalog);

// The measured acceleration spectrum of tool on surface. Throws std::invalid_argument naming the
// catalog and listing the surfaces the tool has (or the tools there are) when there is none; cheap,
// so commands check their pairings before meshing a stylus.
const model::io::VelocitySpectrum& pairing_spectrum(const model::io::Catalog& catalog,
                                                    const std::filesystem::path& catalog_file,
                                                    const std::string& tool,
                                                    const std::string& surface);

// Whether `tool` is a design point to predict ("...tip=2mm") rather than a catalog id.
bool names_design_point(const std::string& tool);

// Design points predicted on demand with one set of prediction inputs (prediction_inputs.hpp),
// loaded the first time a point needs them: the catalog (empty: the bundled one), the forcing model
// from `forcing_model` (empty: fitted to the catalog, ~8 s).
class DesignPredictor {
 public:
  DesignPredictor(std::filesystem::path catalog_file, std::filesystem::path forcing_model);
  ~DesignPredictor();
  // Checks the point (refuses a bad mix or tip before any work) and predicts it on `surface`.
  model::design::PredictedTool predict(const std::string& point, const std::string& surface);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// A voice of a predicted design: its own modes and its predicted spectrum.
std::unique_ptr<rt::Voice> predicted_voice(const model::design::PredictedTool& tool,
                                           double internal_rate, std::uint64_t seed);

// A voice with that spectrum through the stylus's modes (rt/voice_builder.hpp).
std::unique_ptr<rt::Voice> tool_voice(const model::io::Catalog& catalog,
                                      const std::filesystem::path& catalog_file,
                                      const std::string& tool, const std::string& surface,
                                      const StylusModes& stylus, double internal_rate,
                                      std::uint64_t seed);

}  // namespace nibrig::ui::cli
