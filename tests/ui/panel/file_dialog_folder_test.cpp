// A file dialog without a folder of its own opens where a file was last chosen, in any of the
// panel's dialogs, not in the working folder; one given a folder that exists opens there.
#include "ui/panel/file_dialog.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "tests/support/test_paths.hpp"
#include "ui/panel/panel_settings.hpp"

namespace nibrig::ui::panel {
namespace {

// The last folder is kept in the panel's settings: the next start's dialogs open there (they had
// opened in the working folder after every start).
TEST(FileDialogFolder, TheNextStartOpensWhereTheLastOneChoseAFile) {
  const auto dir = std::filesystem::weakly_canonical(nibrig::test::scratch_dir("panel_dialog_folder_kept"));
  std::filesystem::create_directories(dir / "designs");
  std::ofstream(dir / "designs" / "a.json") << "{}";
  FileDialog first;
  first.open("Open a design", FileDialog::Mode::open, {".json"}, dir / "designs", {});
  ASSERT_TRUE(first.choose("a.json"));
  PanelSettings kept;
  kept.dialog_folder = FileDialog::last_folder();
  write_panel_settings(dir / "panel.json", kept);

  FileDialog::remember_last_folder(std::filesystem::current_path());  // as a fresh start has it
  const PanelSettings back = read_panel_settings(dir / "panel.json");
  EXPECT_EQ(back.dialog_folder, dir / "designs");
  FileDialog::remember_last_folder(back.dialog_folder);
  FileDialog next;
  next.open("Replay a recorded stroke", FileDialog::Mode::open, {".csv"}, {}, {});
  EXPECT_EQ(next.folder(), dir / "designs");
  // A folder gone since is not where anything opens.
  FileDialog::remember_last_folder(dir / "gone");
  EXPECT_EQ(FileDialog::last_folder(), dir / "designs");
}

TEST(FileDialogFolder, OpensWhereAFileWasLastChosenUnlessGivenAFolder) {
  const auto dir = std::filesystem::weakly_canonical(nibrig::test::scratch_dir("panel_dialog_folder"));
  std::filesystem::create_directories(dir / "designs");
  std::filesystem::create_directories(dir / "spaces");
  std::ofstream(dir / "designs" / "a.json") << "{}";
  ASSERT_NE(std::filesystem::current_path(), dir / "designs");

  FileDialog first;
  std::filesystem::path taken;
  first.open("Open a design", FileDialog::Mode::open, {".json"}, dir / "designs",
             [&](const std::filesystem::path& f) { taken = f; });
  ASSERT_TRUE(first.choose("a.json"));
  EXPECT_EQ(taken, dir / "designs" / "a.json");
  EXPECT_EQ(FileDialog::last_folder(), dir / "designs");

  // Another dialog (the pad's, say) with no folder, or one that is gone: the last folder used.
  FileDialog second;
  second.open("Replay a recorded stroke", FileDialog::Mode::open, {".csv"}, {}, {});
  EXPECT_EQ(second.folder(), dir / "designs");
  second.open("Save the design", FileDialog::Mode::save, {".json"}, dir / "gone", {});
  EXPECT_EQ(second.folder(), dir / "designs");
  // A folder of its own that exists (the open space's): there.
  second.open("Open a space", FileDialog::Mode::open, {".json"}, dir / "spaces", {});
  EXPECT_EQ(second.folder(), dir / "spaces");
  // Saving there makes it the last folder.
  second.open("Save the space", FileDialog::Mode::save, {".json"}, dir / "spaces", {});
  ASSERT_TRUE(second.choose("b.json"));
  FileDialog third;
  third.open("Export the stylus", FileDialog::Mode::save, {".3mf"}, {}, {});
  EXPECT_EQ(third.folder(), dir / "spaces");
}

}  // namespace
}  // namespace nibrig::ui::panel
