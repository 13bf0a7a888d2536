#include "ui/panel/space_view.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "model/space/catalog_descriptors.hpp"
#include "ui/panel/widgets.hpp"

namespace nibrig::ui::panel {

namespace {

// Colours by surface (a qualitative palette that stays apart on a dark background).
constexpr ImU32 kPalette[] = {IM_COL32(86, 180, 233, 255), IM_COL32(230, 159, 0, 255),
                              IM_COL32(0, 158, 115, 255),  IM_COL32(204, 121, 167, 255),
                              IM_COL32(240, 228, 66, 255), IM_COL32(213, 94, 0, 255),
                              IM_COL32(0, 114, 178, 255),  IM_COL32(200, 200, 200, 255)};

constexpr ImU32 kPlotBackground = IM_COL32(20, 20, 24, 255);
constexpr ImU32 kSoundingColour = IM_COL32(110, 230, 120, 255);

Marker marker_of(const std::string& kind) {
  if (kind == "printed") return Marker::square;
  if (kind == "commercial") return Marker::triangle;
  if (kind == "predicted") return Marker::diamond;
  return Marker::circle;  // a real tool
}

double coordinate(const SceneTool& t, int axis) {
  return axis < t.region.mean.size() ? t.region.mean[axis] : 0.0;
}

}  // namespace

SpaceView::SpaceView(SpaceScene scene, Play play) : play_(std::move(play)) { set_scene(std::move(scene)); }

void SpaceView::set_scene(SpaceScene scene) {
  scene_ = std::move(scene);
  ++generation_;
  const int dims = static_cast<int>(scene_.axis_names.size());
  axis_x_ = 0;
  axis_y_ = dims > 1 ? 1 : 0;
  hovered_.reset();
  chosen_.clear();
}

void SpaceView::set_axes(int x, int y) {
  const int dims = static_cast<int>(scene_.axis_names.size());
  ++generation_;
  axis_x_ = std::clamp(x, 0, std::max(0, dims - 1));
  axis_y_ = std::clamp(y, 0, std::max(0, dims - 1));
}

ImU32 SpaceView::surface_colour(const std::string& surface, int alpha) const {
  static_assert(std::size(kPalette) == kSurfaceSlots);
  const auto at = std::find(scene_.surfaces.begin(), scene_.surfaces.end(), surface);
  const auto k = static_cast<std::size_t>(at - scene_.surfaces.begin());
  // A scene made before slots were given (none known): the order of appearance, as before.
  const std::size_t i = (k < scene_.surface_slots.size() ? scene_.surface_slots[k] : k) % kSurfaceSlots;
  return (kPalette[i] & ~IM_COL32_A_MASK) | (static_cast<ImU32>(alpha) << IM_COL32_A_SHIFT);
}

std::optional<ImVec2> SpaceView::screen_position(std::size_t tool) const {
  if (!frame_ || tool >= scene_.tools.size()) return std::nullopt;
  const auto& t = scene_.tools[tool];
  const bool one_d = scene_.axis_names.size() < 2;
  return frame_->to_screen(coordinate(t, axis_x_), one_d ? 0.0 : coordinate(t, axis_y_));
}

void SpaceView::draw() {
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const float side = side_panel_ ? std::min(340.0f, avail.x * 0.35f) : 0.0f;
  ImGui::BeginChild("space-plot", {avail.x - side - (side_panel_ ? 8.0f : 0.0f), avail.y}, false,
                    ImGuiWindowFlags_NoScrollWithMouse);
  draw_plot(ImGui::GetContentRegionAvail());
  ImGui::EndChild();
  if (!side_panel_) return;
  ImGui::SameLine();
  ImGui::BeginChild("space-side", {side, avail.y});
  draw_side();
  ImGui::EndChild();
}

void SpaceView::draw_plot(ImVec2 size) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 corner = ImGui::GetCursorScreenPos();
  ImGui::TextUnformatted(fitted_from_the_end(scene_.title, size.x).c_str());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", scene_.title.c_str());
  if (scene_.tools.empty()) {
    ImGui::TextWrapped("No space loaded: open one (File > Open space) or wait for the default to be computed.");
    frame_.reset();
    return;
  }
  const bool one_d = scene_.axis_names.size() < 2;
  // The range holds every tool's place and its largest region.
  double x0 = std::numeric_limits<double>::max(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const auto& t : scene_.tools) {
    const double x = coordinate(t, axis_x_), y = one_d ? 0.0 : coordinate(t, axis_y_);
    double reach = 0.0;
    if (!t.region.radius.empty() && t.region.covariance.size() > 0) {
      const auto e = model::space::plane_ellipse(t.region, t.region.radius.size() - 1, axis_x_, one_d ? axis_x_ : axis_y_);
      reach = std::max(e.semi_axis_1, e.semi_axis_2);
    }
    x0 = std::min(x0, x - reach), x1 = std::max(x1, x + reach);
    y0 = std::min(y0, y - reach), y1 = std::max(y1, y + reach);
  }
  for (const auto& p : overlay_places_) {
    if (p.size() <= std::max(axis_x_, axis_y_)) continue;
    x0 = std::min(x0, p[axis_x_]), x1 = std::max(x1, p[axis_x_]);
    if (!one_d) y0 = std::min(y0, p[axis_y_]), y1 = std::max(y1, p[axis_y_]);
  }
  // The legend has a column of its own right of the plot: over the plot it hid the tools under it.
  constexpr const char* kKinds[] = {"real", "printed", "commercial", "predicted"};
  float legend = 0.0f;
  for (const auto& s : scene_.surfaces) legend = std::max(legend, ImGui::CalcTextSize(s.c_str()).x);
  for (const char* kind : kKinds) legend = std::max(legend, ImGui::CalcTextSize(kind).x);
  legend += 28.0f;
  const ImVec2 origin{corner.x + 56.0f, corner.y + 44.0f};
  const ImVec2 plot{std::max(50.0f, size.x - 76.0f - legend), std::max(50.0f, size.y - 96.0f)};
  // Equal units on both axes: distances are the model's, whichever way they point.
  DataRange xr = padded(x0, x1), yr = one_d ? DataRange{-1.0, 1.0} : padded(y0, y1);
  if (!one_d) {
    const double per_px = std::max(xr.span() / plot.x, yr.span() / plot.y);
    const double cx = 0.5 * (xr.min + xr.max), cy = 0.5 * (yr.min + yr.max);
    xr = {cx - per_px * plot.x / 2, cx + per_px * plot.x / 2};
    yr = {cy - per_px * plot.y / 2, cy + per_px * plot.y / 2};
  }
  frame_.emplace(origin, plot, xr, yr);
  // The grid and the regions change only with the scene, the axes and the frame: painted once into
  // a layer (cached_layer.hpp) when there is a window, else live.
  const auto paint = [&](ImDrawList* layer) {
    layer->AddRectFilled(origin, {origin.x + plot.x, origin.y + plot.y}, kPlotBackground);
    draw_grid(layer, *frame_);
    draw_regions(layer, one_d);
  };
  if (CachedLayer::available()) {
    char inputs[160];
    std::snprintf(inputs, sizeof inputs, "%llu %d %d %.17g %.17g %.17g %.17g",
                  static_cast<unsigned long long>(generation_), axis_x_, axis_y_, xr.min, xr.max, yr.min, yr.max);
    regions_.update(std::hash<std::string>{}(inputs), origin, plot, kPlotBackground, paint);
    regions_.draw(draw);
  } else {
    draw->PushClipRect(origin, {origin.x + plot.x, origin.y + plot.y}, true);
    paint(draw);
    draw->PopClipRect();
  }
  draw_axis_labels(draw, *frame_, scene_.axis_names.empty() ? "" : scene_.axis_names[axis_x_],
                   one_d ? "" : scene_.axis_names[axis_y_]);

  // Hover: the nearest point within 9 px.
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  hovered_.reset();
  float best = 9.0f * 9.0f;
  const bool over = ImGui::IsWindowHovered() && frame_->contains(mouse);
  for (std::size_t i = 0; i < scene_.tools.size(); ++i) {
    const ImVec2 p = *screen_position(i);
    const float d = (p.x - mouse.x) * (p.x - mouse.x) + (p.y - mouse.y) * (p.y - mouse.y);
    if (over && d < best) best = d, hovered_ = i;
  }
  for (std::size_t i = 0; i < scene_.tools.size(); ++i) {
    const auto& t = scene_.tools[i];
    const ImVec2 p = *screen_position(i);
    draw_marker(draw, p, marker_of(t.kind), t.judged ? 5.0f : 4.0f, surface_colour(t.choice.surface, 255), t.judged);
    const auto slot = std::find(chosen_.begin(), chosen_.end(), i);
    if (slot != chosen_.end()) {
      const char letter[2] = {static_cast<char>('A' + (slot - chosen_.begin())), 0};
      draw->AddCircle(p, 10.0f, IM_COL32(255, 255, 255, 255), 20, 2.0f);
      draw->AddText({p.x + 10.0f, p.y - 18.0f}, IM_COL32(255, 255, 255, 255), letter);
    }
    if (sounding_ && *sounding_ == t.choice) {  // the one heard now: a second, wider ring in green
      draw->AddCircle(p, 15.0f, kSoundingColour, 24, 3.0f);
      draw->AddText({p.x + 17.0f, p.y - 6.0f}, kSoundingColour, "sounding");
    }
  }
  if (overlay_) {
    draw->PushClipRect(origin, {origin.x + plot.x, origin.y + plot.y}, true);
    overlay_(draw, *frame_, axis_x_, one_d ? axis_x_ : axis_y_);
    draw->PopClipRect();
  }
  // The legend: surfaces by colour, kinds by marker.
  float ly = origin.y + 6.0f;
  const float lx = origin.x + plot.x + 18.0f;
  legend_left_ = lx - 6.0f;
  for (const auto& s : scene_.surfaces) {
    draw->AddCircleFilled({lx, ly + 7.0f}, 4.0f, surface_colour(s, 255));
    draw->AddText({lx + 10.0f, ly}, IM_COL32(230, 230, 230, 255), s.c_str());
    ly += 16.0f;
  }
  for (const char* kind : kKinds) {
    draw_marker(draw, {lx, ly + 7.0f}, marker_of(kind), 4.0f, IM_COL32(230, 230, 230, 255), false);
    draw->AddText({lx + 10.0f, ly}, IM_COL32(230, 230, 230, 255), kind);
    ly += 16.0f;
  }
  ImGui::SetCursorScreenPos(origin);
  ImGui::InvisibleButton("space-canvas", plot);
  if (hovered_) {
    draw_tooltip(scene_.tools[*hovered_]);
    if (ImGui::IsItemClicked(ImGuiMouseButton_Left)) {
      const std::size_t i = *hovered_;
      if (ImGui::GetIO().KeyShift) {  // add to (or take out of) the comparison
        const auto at = std::find(chosen_.begin(), chosen_.end(), i);
        if (at != chosen_.end()) chosen_.erase(at);
        else if (chosen_.size() < 3) chosen_.push_back(i);
      } else {
        chosen_ = {i};
      }
      play_chosen();
    }
  }
}

void SpaceView::play_chosen() {
  if (chosen_.empty() || !play_) return;
  std::vector<ToolChoice> tools;
  for (std::size_t c : chosen_) tools.push_back(scene_.tools[c].choice);
  play_(tools);
}

void SpaceView::draw_regions(ImDrawList* draw, bool one_d) const {
  // 95 % fainter than 68 %, under every point.
  for (const auto& t : scene_.tools) {
    if (t.region.radius.empty() || t.region.covariance.size() == 0) continue;
    for (std::size_t k = 0; k < t.region.radius.size(); ++k) {
      const auto e = model::space::plane_ellipse(t.region, k, axis_x_, one_d ? axis_x_ : axis_y_);
      const int alpha = k == 0 ? 150 : 70;
      draw_ellipse(draw, *frame_, coordinate(t, axis_x_), one_d ? 0.0 : coordinate(t, axis_y_), e.semi_axis_1,
                   one_d ? 0.0 : e.semi_axis_2, e.angle_rad, surface_colour(t.choice.surface, alpha), 1.0f);
    }
  }
}

std::vector<std::string> tooltip_lines(const SceneTool& t) {
  std::vector<std::string> lines{t.label, t.kind + ", " + (t.judged ? "judged" : "placed from its descriptors")};
  char text[160];
  if (t.mu) {
    std::snprintf(text, sizeof text, "mu %.3f", *t.mu);
    lines.emplace_back(text);
  }
  if (t.noise_sigma) {
    std::snprintf(text, sizeof text, "judged with noise sigma %.2f (1 = typical)", *t.noise_sigma);
    lines.emplace_back(text);
  }
  for (const auto& [name, value] : t.descriptors) {
    if (t.mu && name == model::space::kFrictionDescriptor) continue;
    std::snprintf(text, sizeof text, "%s %.3g", name.c_str(), value);
    lines.emplace_back(text);
  }
  return lines;
}

void SpaceView::draw_tooltip(const SceneTool& t) const {
  ImGui::BeginTooltip();
  for (const std::string& line : tooltip_lines(t)) ImGui::TextUnformatted(line.c_str());
  ImGui::EndTooltip();
}

void SpaceView::draw_side() {
  const int dims = static_cast<int>(scene_.axis_names.size());
  if (dims > 2) {
    std::vector<const char*> names;
    for (const auto& n : scene_.axis_names) names.push_back(n.c_str());
    ImGui::Combo("x axis", &axis_x_, names.data(), dims);
    ImGui::Combo("y axis", &axis_y_, names.data(), dims);
  }
  section("Play");
  if (stroke_ && stroke_widgets(*stroke_) && stroke_changed_) stroke_changed_();
  ImGui::TextWrapped("%s", hint_.c_str());
  for (std::size_t k = 0; k < chosen_.size(); ++k) {
    const SceneTool& t = scene_.tools[chosen_[k]];
    const bool sounding = sounding_ && *sounding_ == t.choice;
    // Wrapped, not cut: a long tool name is read whole at any width.
    ImGui::Bullet();
    ImGui::TextWrapped("%c: %s%s", static_cast<char>('A' + k), t.label.c_str(), sounding ? "  (sounding)" : "");
  }
  if (!chosen_.empty() && ImGui::Button("Play again")) play_chosen();
  section("Tools");
  ImGui::Text("%zu tools, %d dimension%s", scene_.tools.size(), dims, dims == 1 ? "" : "s");
  if (!scene_.judgment_model.empty()) {
    section("Judgments");
    ImGui::TextWrapped("judged by %s", scene_.judgment_model.c_str());
    if (!scene_.model_reason.empty()) ImGui::TextWrapped("%s", scene_.model_reason.c_str());
  }
}

}  // namespace nibrig::ui::panel
