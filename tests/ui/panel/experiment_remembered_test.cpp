// The experiment view's study folder and stimulus list are kept between starts of the panel (a
// study runs over days, a participant a start; the form had come back empty every time).
#include <gtest/gtest.h>

#include "tests/ui/panel/panel_test_setup.hpp"
#include "tests/ui/panel/test_space.hpp"
#include "ui/panel/experiment_view.hpp"
#include "ui/panel/file_dialog.hpp"
#include "ui/panel/panel.hpp"
#include "ui/panel/panel_settings.hpp"

namespace nibrig::ui::panel {
namespace {

TEST(ExperimentRemembered, TheStudyFolderAndListComeBackIntoTheFormAtTheNextStart) {
  const auto dir = nibrig::test::scratch_dir("panel_experiment_remembered");
  const auto file = dir / "panel.json";
  PanelWindow window(testing::hidden_window());
  PanelSetup setup;
  setup.space = testing::write_small_space(dir);
  {
    Panel first(setup);
    first.experiment_view().form().study = "/studies/tablets";
    first.experiment_view().form().stimuli = "/studies/tablets.txt";
    first.experiment_view().form().participant = "P07";  // a participant is not kept: the next is another
    write_panel_settings(file, panel_settings_of(first));
  }
  const PanelSettings back = read_panel_settings(file);
  EXPECT_EQ(back.study, "/studies/tablets");
  EXPECT_EQ(back.stimuli, "/studies/tablets.txt");
  Panel next(setup);
  apply_panel_settings(next, back);
  EXPECT_EQ(next.experiment_view().form().study, "/studies/tablets");
  EXPECT_EQ(next.experiment_view().form().stimuli, "/studies/tablets.txt");
  EXPECT_EQ(next.experiment_view().form().participant, "");
}

// Where the last file was chosen comes back too: the next start's dialogs open there.
TEST(ExperimentRemembered, TheDialogsFolderComesBackAtTheNextStart) {
  const auto dir = std::filesystem::weakly_canonical(nibrig::test::scratch_dir("panel_dialog_remembered"));
  std::filesystem::create_directories(dir / "studies");
  PanelWindow window(testing::hidden_window());
  PanelSetup setup;
  setup.space = testing::write_small_space(dir);
  {
    Panel first(setup);
    FileDialog::remember_last_folder(dir / "studies");
    write_panel_settings(dir / "panel.json", panel_settings_of(first));
  }
  FileDialog::remember_last_folder(std::filesystem::current_path());
  Panel next(setup);
  apply_panel_settings(next, read_panel_settings(dir / "panel.json"));
  EXPECT_EQ(FileDialog::last_folder(), dir / "studies");
}

}  // namespace
}  // namespace nibrig::ui::panel
