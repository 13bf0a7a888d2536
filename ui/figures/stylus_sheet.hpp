// A stylus's print sheet: the page that goes to the printer with the files of an export — the
// design, its recipe, its predicted μ and spectrum on the surface it was designed for, and its
// place in the perceptual space with its region and the targets it was designed against. Every
// face's export writes it with the files (export_stylus), so that what is printed carries what was
// predicted of it.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "model/design/predicted_tool.hpp"
#include "model/design/stylus_export.hpp"
#include "model/space/descriptor_map.hpp"
#include "model/space/space_file.hpp"
#include "ui/report/figures.hpp"

namespace nibrig::ui::figures {

// A tool the design was searched against, and how far the design lies from it.
struct SheetTarget {
  std::string name;  // "cryon/office"
  // Where it lies when it was placed from its descriptors; none: a judged stimulus of the space,
  // drawn as the space draws it.
  std::optional<model::space::Placement> placed;
  double distance = 0.0, distance_sd = 0.0;
};

// What the sheet shows beyond the print itself; each part may be missing, and the sheet then says
// what would have given it.
struct StylusSheetInputs {
  const model::design::PredictedTool* tool = nullptr;  // μ and spectrum on its surface
  const model::space::SpaceFile* space = nullptr;
  std::optional<model::space::Placement> placement;  // the design's, in that space
  std::vector<SheetTarget> targets;
  std::string aim = "largest";  // a group's: the largest or mean distance was minimised
};

// The sheet's content as a figure: its text lines (the design, the print's regions with their
// printer materials and volumes, the single-material substitutes, the prediction, the targets and
// the files), the spectrum (one curve per speed) and the space. Throws std::invalid_argument when
// a placement is given without a space, or its dimensions differ from the space's.
report::PrintSheet stylus_sheet(const model::design::StylusPrint& print,
                                const model::design::StylusFiles& files,
                                const StylusSheetInputs& inputs);

// <stem>-sheet.png beside the 3MF.
std::filesystem::path stylus_sheet_path(const std::filesystem::path& three_mf);

struct ExportedStylus {
  model::design::StylusFiles files;
  std::filesystem::path sheet;
};

// The export of every face: write_stylus_files, then the print sheet beside them. Throws what
// those throw, naming the file.
ExportedStylus export_stylus(const std::filesystem::path& three_mf,
                             const model::design::StylusPrint& print,
                             const StylusSheetInputs& inputs);

}  // namespace nibrig::ui::figures
