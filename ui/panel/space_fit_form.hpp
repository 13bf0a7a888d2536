// "Fit a space from judgments" in the window: the judgments file, whether the axes are tied to the
// catalog's descriptors (and a map learnt that places every other tool), the dimensions, λ, the
// judgment model (one of model/space/judgment_model.hpp's families, or "auto": the one that
// predicts held-out judgments best), the starts and the bootstrap's resamples. The panel runs the fit (model/space/space_fit_file.hpp) in
// the background with progress and cancel, and shows the space it makes.
#pragma once

#include <filesystem>
#include <string>

#include "ui/panel/file_dialog.hpp"

namespace nibrig::ui::panel {

struct SpaceFitRequest {
  std::filesystem::path judgments;
  bool descriptors = true;  // the panel's catalog's descriptors of each judged "tool/surface"
  int dims = 2;
  float lambda = 1.0f;  // weight of the descriptor correlation (Eq. 6); 0 without descriptors
  std::string model = "probit";  // a family name, or "auto": chosen by 5-fold cross-validation
  int starts = 16;
  int bootstrap = 200;  // resamples for the 68/95 % regions; 0: none
  int seed = 1;
};

// Its widgets (the judgments chosen through `files`); true when "Fit" was pressed with a request
// that can run (a file named, numbers in range: the fields hold them there).
bool space_fit_form(SpaceFitRequest& request, FileDialog& files);

}  // namespace nibrig::ui::panel
