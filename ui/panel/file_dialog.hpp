// Choosing a file in the window (ImGui has no file dialog): a folder's entries, folders first,
// filtered by what the file is for. As in every desktop file dialog, a click selects an entry (its
// name goes into the text field), a double-click opens it (enters a folder, takes a file), and
// Enter or Open/Save takes what is selected or typed. A path typed whole (absolute, or relative to
// the folder shown) is taken as it is. The listing is a library call (list_folder) that tests reach
// without a screen, and choose() is what Enter and the buttons do.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "imgui.h"

namespace nibrig::ui::panel {

struct FolderEntry {
  std::string name;
  bool folder = false;
  std::uintmax_t bytes = 0;  // 0 for a folder
};

// The folders, then the files whose names end in one of `endings` (all files when empty), each
// sorted by name, case-insensitively; hidden entries (".name") left out. Throws
// std::runtime_error naming the folder when it cannot be read.
std::vector<FolderEntry> list_folder(const std::filesystem::path& folder, const std::vector<std::string>& endings);

class FileDialog {
 public:
  enum class Mode { open, save };
  using Chosen = std::function<void(const std::filesystem::path&)>;

  // Opens the dialog titled `title` in `folder`; when that is empty or missing, in the folder a
  // file was last chosen in (by any dialog), else the working folder. `chosen` is called with
  // the file once a person confirms one.
  void open(std::string title, Mode mode, std::vector<std::string> endings, std::filesystem::path folder,
            Chosen chosen);
  // Each frame: the modal dialog while it is open.
  void draw();
  bool is_open() const { return open_; }
  // The folder of the file last chosen in any dialog (empty: none yet).
  static std::filesystem::path last_folder();
  // As the panel's settings remember it from an earlier start (ignored when not a folder now).
  static void remember_last_folder(const std::filesystem::path& folder);

  // What the buttons do, for scripted sessions: a name (or path) of a folder enters it (false); of
  // a file, takes it (true: the dialog closes and `chosen` is called). False with error() set when
  // the name is empty, names no file to open, or a file to save in a folder that does not exist.
  bool choose(const std::string& name);
  void cancel() { open_ = false; }
  const std::filesystem::path& folder() const { return folder_; }
  const std::vector<FolderEntry>& entries() const { return entries_; }
  const std::string& error() const { return error_; }
  // What the text field holds: the entry last clicked, or what was typed.
  std::string selection() const { return name_; }
  // Where the entry of that name was drawn in the last frame (the centre of its row), for tests
  // that click it; nullopt when it was not drawn.
  std::optional<ImVec2> entry_position(const std::string& name) const;

 private:
  void enter(const std::filesystem::path& folder);

  bool open_ = false, popup_opened_ = false;
  std::string title_;
  Mode mode_ = Mode::open;
  std::vector<std::string> endings_;
  std::filesystem::path folder_;
  std::vector<FolderEntry> entries_;
  Chosen chosen_;
  std::string error_;
  char name_[512] = {};
  std::vector<ImVec2> drawn_at_;  // each entry's row centre in the last frame, as entries_
};

}  // namespace nibrig::ui::panel
