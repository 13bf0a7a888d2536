// View 2, design: a target tool (click it in the space) and its surface; sliders for the mix of two
// materials and the tip diameter; the predicted design moves through the space with its 68/95 %
// regions and plays as the sliders move; "search" runs the line search along the mix or the 2-D
// search over mix × tip toward the target and draws its path (Fig. 17). Live through the
// design-response grid (model/design/design_response_grid.hpp): solved once in the background with
// progress and cancel, cached on disk, interpolated per slider move; its error against the full
// FEM is measured in the background at cell centres and shown. A design loop's rounds
// (loop_rounds.hpp) are drawn over the space when one is opened.
#pragma once

#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "model/design/design_grid_error.hpp"
#include "model/design/design_response_grid.hpp"
#include "model/design/design_search.hpp"
#include "model/design/prediction_inputs.hpp"
#include "model/space/descriptor_map.hpp"
#include "model/space/space_file.hpp"
#include "ui/panel/background_job.hpp"
#include "ui/panel/loop_rounds.hpp"
#include "ui/panel/panel_audio.hpp"
#include "ui/panel/space_view.hpp"

namespace nibrig::ui::panel {

// How finely designs are solved: the defaults are the full template's and the grid's default
// density; the tests ask for a coarse grid so that it solves quickly under the sanitizers.
struct DesignSettings {
  std::string material_a = "vero", material_b = "DM85";
  double min_tip_m = 0.001, max_tip_m = 0.004;
  std::size_t fraction_points = model::design::kDefaultFractionPoints;
  std::size_t tip_points = model::design::kDefaultTipPoints;
  double mesh_size_m = 0.0;  // 0: the template's
  int modes = 0;             // 0: the template's
  std::size_t error_points = 4;  // cell centres the interpolation is checked at against the FEM
};

struct DesignInputs {
  std::shared_ptr<const model::design::PredictionInputs> inputs;
  model::design::DesignResponseGrid grid;
};

// The coarse grid the job hands over while the fine one is solved (the UI takes it when it looks).
struct CoarseHandover {
  std::mutex mutex;
  std::shared_ptr<const model::design::PredictionInputs> inputs;
  std::optional<model::design::DesignResponseGrid> grid;
};

class DesignView {
 public:
  DesignView(PanelAudio& audio, std::filesystem::path catalog, std::filesystem::path forcing,
             DesignSettings settings);
  ~DesignView();

  void draw();
  // The space to design in (the panel's) and its descriptor map (none: designs cannot be placed).
  void set_space(const SpaceScene& scene, std::optional<model::space::DescriptorMap> map);
  // Starts loading the prediction inputs and the grid (once).
  void prepare();
  // Ready once a grid is in use: the coarse one first (a usable view in seconds on first use),
  // then the fine one when it has been solved.
  bool ready() const { return inputs_ != nullptr; }
  bool coarse() const { return coarse_; }
  bool preparing() const { return job_ != nullptr; }
  bool measuring_error() const { return error_job_ != nullptr; }
  // Asks its background work (the grid, the error measurement) to stop; working() is true until
  // that work has ended. The panel replaces a view this way without waiting for a FEM solve.
  void stop_work();
  bool working() const { return (job_ && !job_->done()) || (error_job_ && !error_job_->done()); }

  // The sliders (λ = fraction of material B, tip in mm) and the target, as a person sets them. In
  // group mode a tool clicked joins the targets (or leaves them, clicked again): the searches then
  // find one design for them all (the largest or mean distance, as `aim`); the first target's
  // surface is the one designed for.
  void set_design(double fraction, double tip_mm);
  void set_target(std::size_t tool);
  void set_group_mode(bool group);
  void set_aim(model::space::GroupAim aim) { aim_ = aim; }
  const std::vector<std::size_t>& targets() const { return targets_; }
  // What the searches must keep to (model/design/design_constraints.hpp), as the Constraints
  // section sets them.
  void set_constraints(model::design::DesignConstraints constraints) { constraints_ = std::move(constraints); }
  const model::design::DesignConstraints& constraints() const { return constraints_; }
  void set_playing(bool play) { play_ = play; }
  // Runs the line search (along the mix at the current tip) or the 2-D search within the
  // constraints, toward the target or the group; the path is drawn.
  void search(bool two_d);
  // Writes the design shown as a prediction file (model/design/prediction_file.hpp: what `nibrig
  // predict` writes, so `space embed` and `render --tool` take it). Returns the error, if any.
  std::string save_prediction(const std::filesystem::path& file) const;
  // Sets the sliders to the design a prediction file names. Returns the error, if any: a file that
  // cannot be read (named with its field), a design that mixes other materials than the grid's two,
  // a tip outside the grid.
  std::string open_prediction(const std::filesystem::path& file);
  // Shows a design loop's rounds (its folder, or the loop.json in it) over the space and in a
  // table. Returns the error, if any: a folder that holds no loop, a file that does not read.
  std::string open_loop(const std::filesystem::path& folder_or_file);
  const std::optional<LoopRounds>& loop() const { return loop_; }

  // The design shown made printable (ui/figures/stylus_sheet.hpp export_stylus: the 3MF, an STL
  // per region, the recipe and the print sheet beside `file`), as work to run off the UI thread: it
  // meshes and solves the stylus. With `space` (the one shown) and a target the sheet places the
  // design and gives its distance to the target. It holds copies of what it needs, so the view may
  // change meanwhile; it throws what the export throws. Empty when no design is shown yet.
  std::function<void()> stylus_export(const std::filesystem::path& file,
                                      std::optional<model::space::SpaceFile> space = std::nullopt) const;
  // The printer the export is for (a profile's name or file; empty: none, its settings unstated):
  // the 3MF then carries its slicer settings, and a design it cannot make is refused, naming why.
  void set_printer(std::string name) { printer_ = std::move(name); }
  const std::string& printer() const { return printer_; }

  // What the view shows, for tests and the status: the current prediction and its placement,
  // how long the last slider move took to a placement and a loaded sound, the last search, the
  // measured interpolation error.
  const std::optional<model::design::PredictedTool>& predicted() const { return predicted_; }
  const std::optional<model::space::Placement>& placement() const { return placement_; }
  double last_update_ms() const { return last_update_ms_; }
  // When the last move's sound was handed to the audio thread (what follows is the audio's part).
  std::chrono::steady_clock::time_point last_sound_sent() const { return last_sound_sent_; }
  const std::optional<model::design::SearchResult>& last_search() const { return search_; }
  const std::optional<model::design::GridError>& grid_error() const { return grid_error_; }
  const std::optional<model::design::DesignResponseGrid>& grid() const { return grid_; }
  // What the grid's job says it is doing (empty when none runs).
  std::string progress_message() const { return job_ ? job_->message() : std::string(); }
  const std::string& error() const { return error_; }
  SpaceView& space() { return *space_; }
  // Where the mix slider was last drawn (a scripted session drags it).
  std::pair<ImVec2, ImVec2> mix_slider_rect() const { return mix_slider_; }

 private:
  // The prediction (and placement) at the sliders; `sound`: it plays too (a person moved something,
  // never a space or grid that merely arrived).
  void update_design(bool sound);
  // Whether the sound heard now is this view's design (a grid that arrives replaces it then).
  bool design_heard() const;
  void take_grids();
  void start_error_job();
  void draw_printer_choice();
  void draw_controls();
  void draw_target_controls();
  void draw_constraint_controls();
  // The evaluation the searches use: toward the target, or the group's aggregate.
  model::design::Evaluate search_evaluation() const;
  void draw_overlay(ImDrawList* draw, const PlotFrame& frame, int ax, int ay) const;
  // The loop's places the plot must hold, and its target's place in the scene shown.
  void place_loop();
  std::string surface() const;

  PanelAudio& audio_;
  std::filesystem::path catalog_, forcing_;
  DesignSettings settings_;
  std::unique_ptr<SpaceView> space_;
  std::optional<model::space::DescriptorMap> map_;
  std::unique_ptr<BackgroundJob<DesignInputs>> job_;
  std::unique_ptr<BackgroundJob<model::design::GridError>> error_job_;
  bool error_stale_ = false;  // the space changed while the error was measured: measure again
  std::shared_ptr<const model::design::PredictionInputs> inputs_;
  std::shared_ptr<CoarseHandover> coarse_handover_;
  bool coarse_ = false;
  std::optional<model::design::DesignResponseGrid> grid_;
  std::vector<std::size_t> targets_;  // indices into the scene's tools; the first sets the surface
  bool group_mode_ = false;
  model::space::GroupAim aim_ = model::space::GroupAim::largest;
  std::string printer_;
  std::vector<std::string> printer_names_;  // for the choice: bundled, then the lab's own
  model::design::DesignConstraints constraints_;
  float fraction_ = 0.5f, tip_mm_ = 2.0f;
  bool play_ = true;
  std::optional<model::design::PredictedTool> predicted_;
  std::optional<model::space::Placement> placement_;
  std::optional<model::design::SearchResult> search_;
  std::optional<model::design::GridError> grid_error_;
  double last_update_ms_ = 0.0, last_search_ms_ = 0.0;
  std::chrono::steady_clock::time_point last_sound_sent_{};
  std::string error_;
  std::pair<ImVec2, ImVec2> mix_slider_{};
  std::optional<LoopRounds> loop_;
};

}  // namespace nibrig::ui::panel
