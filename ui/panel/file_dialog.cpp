#include "ui/panel/file_dialog.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <system_error>

#include "imgui.h"

namespace nibrig::ui::panel {

namespace fs = std::filesystem;

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool ends_in_one_of(const std::string& name, const std::vector<std::string>& endings) {
  if (endings.empty()) return true;
  const std::string n = lower(name);
  return std::any_of(endings.begin(), endings.end(), [&](const std::string& e) { return n.ends_with(lower(e)); });
}

std::string size_text(std::uintmax_t bytes) {
  char text[32];
  if (bytes < 1024) std::snprintf(text, sizeof text, "%ju B", bytes);
  else if (bytes < 1024 * 1024) std::snprintf(text, sizeof text, "%.1f KiB", static_cast<double>(bytes) / 1024.0);
  else std::snprintf(text, sizeof text, "%.1f MiB", static_cast<double>(bytes) / (1024.0 * 1024.0));
  return text;
}

}  // namespace

std::vector<FolderEntry> list_folder(const fs::path& folder, const std::vector<std::string>& endings) {
  std::error_code ec;
  fs::directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec);
  if (ec) throw std::runtime_error(folder.string() + ": cannot be read (" + ec.message() + ")");
  std::vector<FolderEntry> folders, files;
  for (; it != fs::directory_iterator(); it.increment(ec)) {
    if (ec) throw std::runtime_error(folder.string() + ": cannot be read (" + ec.message() + ")");
    const std::string name = it->path().filename().string();
    if (name.starts_with(".")) continue;
    std::error_code kind;
    if (it->is_directory(kind)) folders.push_back({name, true, 0});
    else if (ends_in_one_of(name, endings)) files.push_back({name, false, it->is_regular_file(kind) ? it->file_size(kind) : 0});
  }
  const auto by_name = [](const FolderEntry& a, const FolderEntry& b) {
    const std::string la = lower(a.name), lb = lower(b.name);
    return la != lb ? la < lb : a.name < b.name;
  };
  std::sort(folders.begin(), folders.end(), by_name);
  std::sort(files.begin(), files.end(), by_name);
  folders.insert(folders.end(), files.begin(), files.end());
  return folders;
}

namespace {

// Where a file was last chosen, in any of the panel's dialogs: where the next one without a
// folder of its own opens (a person's files are rarely in the folder the panel was started in).
fs::path& file_dialog_last_folder() {
  static fs::path folder;
  return folder;
}

}  // namespace

fs::path FileDialog::last_folder() { return file_dialog_last_folder(); }

void FileDialog::remember_last_folder(const fs::path& folder) {
  std::error_code ec;
  if (!folder.empty() && fs::is_directory(folder, ec)) file_dialog_last_folder() = folder;
}

void FileDialog::open(std::string title, Mode mode, std::vector<std::string> endings, fs::path folder, Chosen chosen) {
  title_ = std::move(title);
  mode_ = mode;
  endings_ = std::move(endings);
  chosen_ = std::move(chosen);
  name_[0] = 0;
  error_.clear();
  std::error_code ec;
  if (folder.empty() || !fs::is_directory(folder, ec)) folder = file_dialog_last_folder();
  if (folder.empty() || !fs::is_directory(folder, ec)) folder = fs::current_path(ec);
  enter(folder);
  open_ = true;
  popup_opened_ = false;
}

std::optional<ImVec2> FileDialog::entry_position(const std::string& name) const {
  for (std::size_t i = 0; i < entries_.size() && i < drawn_at_.size(); ++i)
    if (entries_[i].name == name) return drawn_at_[i];
  return std::nullopt;
}

void FileDialog::enter(const fs::path& folder) {
  std::error_code ec;
  const fs::path absolute = fs::weakly_canonical(fs::absolute(folder, ec), ec);
  try {
    entries_ = list_folder(absolute, endings_);
    drawn_at_.clear();  // until the new listing is drawn
    folder_ = absolute;
    error_.clear();
  } catch (const std::exception& e) {
    error_ = e.what();  // stay where we were
  }
}

bool FileDialog::choose(const std::string& name) {
  if (name.empty()) {
    error_ = mode_ == Mode::open ? "choose a file to open" : "type a name to save as";
    return false;
  }
  const fs::path path = fs::path(name).is_absolute() ? fs::path(name) : folder_ / name;
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    enter(path);
    name_[0] = 0;
    return false;
  }
  if (mode_ == Mode::open && !fs::is_regular_file(path, ec)) {
    error_ = path.string() + ": no such file";
    return false;
  }
  if (mode_ == Mode::save && !fs::is_directory(path.parent_path(), ec)) {
    error_ = path.parent_path().string() + ": no such folder";
    return false;
  }
  open_ = false;
  error_.clear();
  const fs::path taken = fs::weakly_canonical(path, ec);
  file_dialog_last_folder() = taken.parent_path();
  if (chosen_) chosen_(taken);
  return true;
}

void FileDialog::draw() {
  if (!open_) return;
  const std::string id = title_ + "##file-dialog";
  if (!popup_opened_) {
    ImGui::OpenPopup(id.c_str());
    popup_opened_ = true;
  }
  const ImVec2 size = ImGui::GetMainViewport()->WorkSize;
  ImGui::SetNextWindowSize({std::min(720.0f, size.x - 40.0f), std::min(520.0f, size.y - 40.0f)}, ImGuiCond_Appearing);
  bool keep = true;
  if (!ImGui::BeginPopupModal(id.c_str(), &keep)) {
    open_ = keep && open_;
    return;
  }
  if (ImGui::Button("Up")) enter(folder_.parent_path());
  ImGui::SameLine();
  ImGui::TextUnformatted(folder_.c_str());
  const float footer = ImGui::GetFrameHeightWithSpacing() * 2.0f + ImGui::GetTextLineHeightWithSpacing();
  ImGui::BeginChild("entries", {0.0f, -footer}, true);
  // A click selects; a double-click opens. ImGui reports a double-click as a second press on the
  // entry the first one selected; it is acted on after the loop, which it would invalidate.
  std::string open_now;
  drawn_at_.assign(entries_.size(), ImVec2{});
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    const FolderEntry& e = entries_[i];
    const std::string label = e.folder ? e.name + "/" : e.name;
    if (ImGui::Selectable(label.c_str(), e.name == name_, ImGuiSelectableFlags_AllowDoubleClick)) {
      std::snprintf(name_, sizeof name_, "%s", e.name.c_str());
      if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) open_now = e.name;
    }
    const ImVec2 low = ImGui::GetItemRectMin(), high = ImGui::GetItemRectMax();
    drawn_at_[i] = {0.5f * (low.x + high.x), 0.5f * (low.y + high.y)};
    if (!e.folder) {
      ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - 90.0f);
      ImGui::TextDisabled("%s", size_text(e.bytes).c_str());
    }
  }
  ImGui::EndChild();
  if (!open_now.empty()) choose(open_now);
  ImGui::SetNextItemWidth(-200.0f);
  // The name field has the keyboard when the dialog opens, as in a desktop dialog: a name can be
  // typed at once.
  if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
  // Enter takes what the field holds, whether it was being edited (typed: the field reports that
  // Enter itself) or not (the list had the focus after a click); one call either way.
  const bool typed = ImGui::InputText("##name", name_, sizeof name_, ImGuiInputTextFlags_EnterReturnsTrue);
  const bool enter_key = ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false) ||
                         ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_KeyPadEnter), false);
  ImGui::SameLine();
  const bool button = ImGui::Button(mode_ == Mode::open ? "Open" : "Save");
  if (open_ && (button || typed || enter_key)) choose(name_);
  ImGui::SameLine();
  if (ImGui::Button("Cancel")) open_ = false;
  if (!error_.empty()) ImGui::TextColored({1.0f, 0.45f, 0.4f, 1.0f}, "%s", error_.c_str());
  else if (mode_ == Mode::save && name_[0] && fs::exists(folder_ / name_))
    ImGui::TextDisabled("%s exists and will be replaced", name_);
  else ImGui::TextDisabled("%s", endings_.empty() ? "any file" : ("files ending in " + endings_.front()).c_str());
  if (!open_) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
  if (!keep) open_ = false;
}

}  // namespace nibrig::ui::panel
