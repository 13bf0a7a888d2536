#include "ui/figures/stylus_sheet.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "model/design/slicer_settings.hpp"
#include "model/io/atomic_file.hpp"
#include "model/mechanics/region_surface.hpp"
#include "ui/figures/predicted_text.hpp"
#include "ui/figures/space_scatter.hpp"

namespace nibrig::ui::figures {

namespace design = model::design;

namespace {

using Lines = std::vector<report::SheetLine>;

void heading(Lines& lines, std::string text) { lines.push_back({std::move(text), true}); }
void line(Lines& lines, std::string text) { lines.push_back({std::move(text), false}); }

// `targets`: how the substitutes' distance to what the design was searched for reads ("target",
// or "targets (largest)" for a group).
void print_lines(Lines& lines, const design::StylusPrint& print, const design::StylusFiles& files,
                 const std::string& targets) {
  heading(lines, "Design");
  line(lines, design::to_string(print.point));
  line(lines, fmt::format("meshed at {:.2f} mm, as the prediction solved it", print.design.mesh_size * 1e3));
  heading(lines, fmt::format("Print: one part of {} object{} ({})", print.regions.size(),
                             print.regions.size() == 1 ? "" : "s", files.three_mf.filename().string()));
  for (const auto& region : print.regions) {
    std::string basis;
    for (const auto& m : print.materials.materials())
      if (m.name == region.material) basis = " (" + model::mechanics::describe_basis(m) + ")";
    line(lines, fmt::format("{}: {}, {:.1f} mm3{}", region.surface.name, design::printer_material(region),
                            model::mechanics::enclosed_volume(region.surface) * 1e9, basis));
  }
  if (print.printer) {
    const auto& p = *print.printer;
    heading(lines, "Printer: " + p.name);
    line(lines, p.printer);
    line(lines, design::describe_print_settings(p));
    if (!files.slicer_config.empty())
      line(lines, "slice: " + design::prusa_slicer_command(p, files.slicer_config.filename(), files.three_mf.filename()));
    else
      line(lines, "slicer: " + p.slicer);
  } else {
    line(lines, "no printer given (--printer): the slicer's defaults are not a solid part");
  }
  if (!print.substitutes.empty()) {
    heading(lines, "Without mixing (distance in the space)");
    for (const auto& s : print.substitutes)
      line(lines, fmt::format("{}: {:.3f} ± {:.3f} from this design{}{}", design::label(s.point), s.cost, s.cost_sd,
                              s.to_target ? fmt::format(", {:.3f} ± {:.3f} from the {}", *s.to_target, s.to_target_sd, targets)
                                          : std::string(),
                              s.outside_constraints.empty() ? "" : "; outside the constraints: " + s.outside_constraints));
  }
}

report::LinePlot spectrum_plot(const design::PredictedTool& tool) {
  report::LinePlot plot;
  plot.title = "Predicted vibration on " + tool.surface;
  plot.x_label = "frequency (Hz)";
  plot.y_label = "amplitude (m/s#u2#d)";
  plot.log_y = true;
  const auto& s = tool.spectrum;
  for (std::size_t v = 0; v < s.speeds_m_s.size(); ++v) {
    report::LineSeries series;
    series.label = fmt::format("{:g} mm/s", s.speeds_m_s[v] * 1e3);
    for (std::size_t f = 0; f < s.frequencies_hz.size(); ++f) {
      const double a = s.amplitude_m_s2[v][f];
      if (a <= 0.0) continue;  // silent bins have no place on a log axis
      series.x.push_back(s.frequencies_hz[f]);
      series.y.push_back(a);
    }
    if (!series.x.empty()) plot.series.push_back(std::move(series));
  }
  return plot;
}

}  // namespace

report::PrintSheet stylus_sheet(const design::StylusPrint& print, const design::StylusFiles& files,
                                const StylusSheetInputs& inputs) {
  if (inputs.placement && inputs.space == nullptr)
    throw std::invalid_argument("stylus sheet: the design has a placement but no space to draw it in");
  if (inputs.placement && inputs.placement->mean.size() != inputs.space->coordinates.rows())
    throw std::invalid_argument(fmt::format(
        "stylus sheet: the design's placement has {} dimensions, the space {}",
        inputs.placement->mean.size(), inputs.space->coordinates.rows()));

  report::PrintSheet sheet;
  sheet.title = "nibrig stylus " + design::label(print.point);
  print_lines(sheet.lines, print, files,
              inputs.targets.size() > 1 ? "targets (" + inputs.aim + ")" : std::string("target"));

  heading(sheet.lines, inputs.tool ? "Predicted on " + inputs.tool->surface : "Predicted");
  if (inputs.tool) {
    line(sheet.lines, describe_descriptors(*inputs.tool));
    line(sheet.lines, fmt::format("first mode {:.0f} Hz", inputs.tool->first_mode_hz));
    const auto plot = spectrum_plot(*inputs.tool);
    if (!plot.series.empty()) sheet.line_plot = plot;
  } else {
    line(sheet.lines, "not on this sheet: give the surface the stylus is for");
  }

  if (!inputs.targets.empty()) {
    heading(sheet.lines, inputs.targets.size() == 1 ? "Target" : "Targets");
    for (const auto& t : inputs.targets)
      line(sheet.lines, fmt::format("{}: distance {:.3f} ± {:.3f}", t.name, t.distance, t.distance_sd));
  }
  if (inputs.space != nullptr && inputs.placement) {
    std::vector<PlacedTool> placed;
    for (const auto& t : inputs.targets)
      if (t.placed) placed.push_back({t.name, *t.placed, "target", true});
    placed.push_back({"this design", *inputs.placement, "this design", true});
    sheet.scatter_plot = space_scatter(*inputs.space, placed, "Where it lies in the perceptual space");
    sheet.scatter_plot->leave_out_crowded_labels = true;  // a third of a page: labels must be readable
  } else {
    line(sheet.lines, "its place in the space: not on this sheet (no space given)");
  }

  heading(sheet.lines, "Files");
  line(sheet.lines, files.three_mf.filename().string());
  for (const auto& stl : files.stls) line(sheet.lines, stl.filename().string());
  if (!files.slicer_config.empty())
    line(sheet.lines, files.slicer_config.filename().string() + " (the slicer's settings)");
  line(sheet.lines, files.recipe.filename().string() + " (the recipe)");
  return sheet;
}

std::filesystem::path stylus_sheet_path(const std::filesystem::path& three_mf) {
  return three_mf.parent_path() / (three_mf.stem().string() + "-sheet.png");
}

ExportedStylus export_stylus(const std::filesystem::path& three_mf, const design::StylusPrint& print,
                             const StylusSheetInputs& inputs) {
  // The sheet is made before anything is written, so that its refusals leave no files behind; the
  // files then appear together or not at all.
  const auto sheet = stylus_sheet(print, design::stylus_files(three_mf, print), inputs);
  model::io::refuse_companion_link(stylus_sheet_path(three_mf), three_mf);
  model::io::OutputSet files;
  ExportedStylus out{design::write_stylus_files(three_mf, print), stylus_sheet_path(three_mf)};
  report::write_print_sheet(sheet, out.sheet);
  files.commit();
  return out;
}

}  // namespace nibrig::ui::figures
