// View 1, the space: every tool where people perceive it (Fig. 9, 15), with its 68 % and 95 %
// regions, coloured by surface and marked by kind; a choice of axes for spaces of more than two
// dimensions; hover for the tool, its μ and descriptors; click to play it, shift-click to add it
// to an A/B or triplet comparison of up to three.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "model/space/bootstrap.hpp"
#include "ui/panel/cached_layer.hpp"
#include "ui/panel/panel_audio.hpp"
#include "ui/panel/plot_frame.hpp"
#include "ui/panel/stroke_choice.hpp"

namespace nibrig::ui::panel {

// One tool as the view draws it.
struct SceneTool {
  ToolChoice choice;        // what plays when it is clicked
  std::string label;        // "Crayon on office paper"
  std::string kind;         // real | printed | commercial | predicted
  bool judged = false;      // a stimulus of the judgments (else placed from its descriptors)
  model::space::ConfidenceRegion region;  // mean = its place; no radii: no region known
  std::vector<double> region_levels;      // the levels of region.radius
  std::optional<double> mu;
  std::optional<double> noise_sigma;  // how consistently it was judged (1 = typical), when known
  std::vector<std::pair<std::string, double>> descriptors;
};

// How many colours surfaces are drawn in (SpaceScene::surface_slots index them).
inline constexpr std::size_t kSurfaceSlots = 8;

struct SpaceScene {
  std::string title;  // where the space comes from, e.g. "SIMULATED observer" when it is
  std::vector<std::string> axis_names;  // one per dimension
  std::vector<SceneTool> tools;
  std::vector<std::string> surfaces;  // as they first appear among the tools
  // Each surface's colour, by name (surface_slots): the same surface has the same colour in
  // every space, where the order of appearance had made glass pink in one space, green in another.
  std::vector<std::size_t> surface_slots;  // as surfaces
  std::string judgment_model;         // the space's model and its fitted parts, in words
  std::string model_reason;           // why that model
};

// What a tool's tooltip says, line by line: its name, kind, μ, how it was judged, its descriptors
// (μ once, though it is a descriptor too).
std::vector<std::string> tooltip_lines(const SceneTool& tool);

class SpaceView {
 public:
  // `play` is called with one to three tools when a person asks to hear them.
  using Play = std::function<void(const std::vector<ToolChoice>&)>;
  SpaceView(SpaceScene scene, Play play);

  void draw();
  void set_scene(SpaceScene scene);
  // Drawn over the tools each frame (the design view's design point, its regions and its search
  // path), with the plot's mapping and the axes shown.
  using Overlay = std::function<void(ImDrawList*, const PlotFrame&, int axis_x, int axis_y)>;
  void set_overlay(Overlay overlay) { overlay_ = std::move(overlay); }
  // Places the overlay draws (a design loop's prints) that the plot's range must hold too.
  void set_overlay_places(std::vector<Eigen::VectorXd> places) {
    overlay_places_ = std::move(places);
  }
  // Without its side panel (axes, stroke, chosen tools): the design view has its own controls.
  void set_side_panel(bool shown) { side_panel_ = shown; }
  // The hint under "Play" (what a click does in this view).
  void set_hint(std::string hint) { hint_ = std::move(hint); }
  const SpaceScene& scene() const { return scene_; }
  // For tests and the status line: the tool under the mouse, the chosen ones, the plot's mapping.
  std::optional<std::size_t> hovered() const { return hovered_; }
  const std::vector<std::size_t>& chosen() const { return chosen_; }
  const std::optional<PlotFrame>& frame() const { return frame_; }
  int axis_x() const { return axis_x_; }
  int axis_y() const { return axis_y_; }
  void set_axes(int x, int y);
  // Plays the chosen tools again (the "Play again" button, the Enter key).
  void play_chosen();
  // The side panel edits this stroke (the panel's one setting); `changed` is called when it does.
  // None: the side panel shows no stroke.
  void share_stroke(StrokeChoice* stroke, std::function<void()> changed) {
    stroke_ = stroke;
    stroke_changed_ = std::move(changed);
  }
  // The tool sounding now (marked in the plot and the side panel), if it is one of the scene's.
  void set_sounding(std::optional<ToolChoice> tool) { sounding_ = std::move(tool); }
  const std::optional<ToolChoice>& sounding() const { return sounding_; }
  // The colour tools on that surface are drawn in (alpha 0-255).
  ImU32 surface_colour(const std::string& surface, int alpha) const;
  // Where tool i is drawn on the screen (after a draw()).
  std::optional<ImVec2> screen_position(std::size_t tool) const;
  // Where the legend's column starts, right of the plot (after a draw()).
  float legend_left() const { return legend_left_; }

 private:
  void draw_plot(ImVec2 size);
  void draw_side();
  void draw_tooltip(const SceneTool& tool) const;
  void draw_regions(ImDrawList* draw, bool one_d) const;

  SpaceScene scene_;
  Play play_;
  int axis_x_ = 0, axis_y_ = 1;
  std::optional<std::size_t> hovered_;
  std::vector<std::size_t> chosen_;
  std::optional<PlotFrame> frame_;
  StrokeChoice* stroke_ = nullptr;
  std::function<void()> stroke_changed_;
  std::optional<ToolChoice> sounding_;
  float legend_left_ = 0.0f;
  CachedLayer regions_;
  Overlay overlay_;
  std::vector<Eigen::VectorXd> overlay_places_;
  bool side_panel_ = true;
  std::string hint_ = "Click a tool to feel it; shift-click to compare up to three (A, B, C).";
  std::uint64_t generation_ = 0;  // bumped when the scene or the axes change
};

}  // namespace nibrig::ui::panel
