// "Tool X on surface Y" made into what a real-time voice plays: the modes of a stylus and the
// acceleration spectrum it is driven with. A catalog tool is its measured spectrum through the
// modes of a stylus design (by default the bundled printed stylus with a 2 mm tip); a design point
// ("DM85:0.5,vero:0.5,tip=2mm"), or a printed tool the catalog has not measured ("PLA-1mm"), is
// predicted (Sec. 5.3) with its own modes. Whatever plays a tool asks here.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "model/design/predicted_tool.hpp"
#include "model/forcing/forcing_inputs.hpp"
#include "model/io/catalog_file.hpp"
#include "model/io/velocity_spectrum.hpp"
#include "model/modal/modal_model.hpp"
#include "model/modal/voice_source.hpp"

namespace nibrig::model::design {

// A tool's sound is what a voice is made of, as it is: the engine and players take it unchanged.
using ToolSound = modal::VoiceSource;

// What a voice plays for a predicted design: its modes and predicted spectrum, named "predicted
// <point> on <surface>". The one naming for a full prediction and for one from the design grid.
ToolSound predicted_sound(PredictedTool tool);

// Whether `tool` is a design point to predict ("...tip=2mm") rather than a catalog id.
bool names_design_point(const std::string& tool);

// A printed tool's id that `catalog` has not measured ("PLA-1mm", a lab's first print of a
// material it calibrates; catalog/tool_names.hpp): the design point it is printed as, which is
// played as predicted. Nothing for a catalog's own tool or an id that names no printed tool.
std::optional<DesignPoint> unmeasured_print(const io::Catalog& catalog, const std::string& tool);

// The measured acceleration spectrum of tool on surface. Throws std::invalid_argument naming the
// catalog (`catalog_file`; empty: "the bundled catalog") and listing the surfaces the tool has (or
// the tools there are) when there is none; cheap, so faces check their pairings before meshing.
const io::VelocitySpectrum& pairing_spectrum(const io::Catalog& catalog,
                                             const std::filesystem::path& catalog_file,
                                             const std::string& tool, const std::string& surface);

struct ToolSoundOptions {
  std::filesystem::path catalog;        // empty: the bundled one
  std::filesystem::path stylus_design;  // modes of catalog tools; empty: the bundled 2 mm stylus
  std::filesystem::path forcing_model;  // for design points; empty: fit the catalog (~8 s) first
  forcing::DesignProgress progress;     // of that fit's simulated designs
};

// Makes the sounds of any number of tools with one set of inputs, each loaded the first time a
// tool needs it: the stylus's modes once for all catalog tools (from the user cache where another
// process solved them, stylus_modes.hpp), the forcing model read (or fitted) once for all design
// points.
// Whether a tool name is a design point ("DM85:0.5,vero:0.5,tip=2mm") rather than a catalog id.
bool names_design_point(const std::string& tool);

class ToolSounds {
 public:
  explicit ToolSounds(ToolSoundOptions options);  // reads the catalog; throws naming a bad one
  ~ToolSounds();
  ToolSounds(const ToolSounds&) = delete;
  ToolSounds& operator=(const ToolSounds&) = delete;

  // Refuses, before any meshing or fitting, a tool the catalog does not have on the surface or a
  // malformed design point (std::invalid_argument saying which and what there is).
  void check(const std::string& tool, const std::string& surface) const;
  ToolSound sound(const std::string& tool, const std::string& surface);
  // Whether sound() for this catalog tool solves the stylus's modes first (seconds; once, then
  // kept in the user cache; never when the build shipped them): what a face tells a person who
  // waits.
  bool solves_stylus_modes() const;
  // A design point's full prediction (its descriptors, μ, response), for faces that show them.
  PredictedTool predict(const std::string& point, const std::string& surface);
  const io::Catalog& catalog() const;

 private:
  const PredictionSetup& prediction_setup();
  ToolSound print_sound(const DesignPoint& point, const std::string& surface);
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace nibrig::model::design
