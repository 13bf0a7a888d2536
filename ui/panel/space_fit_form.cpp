#include "ui/panel/space_fit_form.hpp"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "imgui.h"
#include "model/space/judgment_model.hpp"

namespace nibrig::ui::panel {

bool space_fit_form(SpaceFitRequest& r, FileDialog& files) {
  char path[512];
  std::snprintf(path, sizeof path, "%s", r.judgments.c_str());
  if (ImGui::InputText("judgments", path, sizeof path)) r.judgments = path;
  ImGui::SameLine();
  if (ImGui::Button("Browse##judgments"))
    files.open("Judgments", FileDialog::Mode::open, {".csv", ".csv.gz", ".json"}, r.judgments.parent_path(),
               [&r](const std::filesystem::path& chosen) { r.judgments = chosen; });
  ImGui::Checkbox("tie the axes to the catalog's descriptors", &r.descriptors);
  ImGui::SliderInt("dimensions", &r.dims, 1, 6);
  if (r.descriptors) ImGui::SliderFloat("lambda", &r.lambda, 0.0f, 10.0f, "%.2f");
  if (ImGui::BeginCombo("judgment model", r.model.c_str())) {
    std::vector<std::string> names{"auto"};
    for (const auto& f : model::space::every_family()) names.push_back(model::space::family_name(f));
    for (const auto& name : names)
      if (ImGui::Selectable(name.c_str(), name == r.model)) r.model = name;
    ImGui::EndCombo();
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("auto: the model that predicts held-out judgments best (5-fold cross-validation)");
  ImGui::SliderInt("starts", &r.starts, 1, 64);
  ImGui::SliderInt("bootstrap resamples", &r.bootstrap, 0, 1000);
  ImGui::InputInt("seed", &r.seed);
  // Typed values (ctrl-click on a slider) are held in range as the fields show them.
  r.dims = std::clamp(r.dims, 1, 6);
  r.starts = std::clamp(r.starts, 1, 64);
  r.bootstrap = std::clamp(r.bootstrap, 0, 1000);
  r.seed = std::max(r.seed, 0);
  r.lambda = std::clamp(r.lambda, 0.0f, 10.0f);
  ImGui::BeginDisabled(r.judgments.empty());
  const bool fit = ImGui::Button("Fit");
  ImGui::EndDisabled();
  return fit && !r.judgments.empty();
}

}  // namespace nibrig::ui::panel
