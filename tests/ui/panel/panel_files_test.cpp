// The files a person opens and saves in the panel, and its keys: the file dialog's listing and
// choices; a space fitted from a judgments file in the window (in the background, with progress),
// shown, saved and opened again; a catalog that cannot be read leaves everything as it was, with
// the file named in the error line, and one that can replaces the one in use; the keys switch
// views and the compared tools. In a hidden window on Xvfb, as a person would use it.
#include <GLFW/glfw3.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <functional>
#include <thread>

#include "model/forcing/forcing_store.hpp"
#include "model/io/bundled_assets.hpp"
#include "model/io/triplets.hpp"
#include "model/space/fit.hpp"
#include "model/space/model_choice.hpp"
#include "model/space/space_file.hpp"
#include "model/space/space_inputs.hpp"
#include "tests/model/design/hand_made_forcing_model.hpp"
#include "tests/model/space/study_fixture.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/ui/panel/panel_test_setup.hpp"
#include "tests/ui/panel/test_space.hpp"
#include "ui/panel/file_dialog.hpp"
#include "ui/panel/panel.hpp"
#include "ui/panel/panel_window.hpp"

namespace nibrig::ui::panel {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

void touch(const fs::path& file) { std::ofstream(file) << "{}"; }

TEST(FileDialog, ListsFoldersFirstThenTheFilesItIsForByName) {
  const auto dir = nibrig::test::scratch_dir("file_dialog_list");
  for (const char* name : {"b.json", "A.json", "notes.txt", ".hidden.json"}) touch(dir / name);
  fs::create_directories(dir / "zeta");
  fs::create_directories(dir / "Alpha");
  const auto entries = list_folder(dir, {".json"});
  std::vector<std::string> names;
  for (const auto& e : entries) names.push_back(e.name + (e.folder ? "/" : ""));
  EXPECT_EQ(names, (std::vector<std::string>{"Alpha/", "zeta/", "A.json", "b.json"}));
  EXPECT_EQ(entries[2].bytes, 2u);
  EXPECT_EQ(list_folder(dir, {}).size(), 5u);  // the text file too; never the hidden one
  try {
    list_folder(dir / "missing", {".json"});
    FAIL() << "a missing folder was listed";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("missing"));
  }
}

TEST(FileDialog, AChoiceEntersAFolderOrTakesAFile) {
  const auto dir = nibrig::test::scratch_dir("file_dialog_choose");
  fs::create_directories(dir / "sub");
  touch(dir / "space.json");
  fs::path taken;
  FileDialog dialog;
  dialog.open("Open a space", FileDialog::Mode::open, {".json"}, dir / "sub",
              [&](const fs::path& f) { taken = f; });
  EXPECT_TRUE(dialog.is_open());
  EXPECT_TRUE(dialog.entries().empty());
  EXPECT_FALSE(dialog.choose(".."));  // a folder: entered
  EXPECT_EQ(dialog.folder(), fs::canonical(dir));
  EXPECT_EQ(dialog.entries().size(), 2u);
  EXPECT_FALSE(dialog.choose("nothing.json"));
  EXPECT_THAT(dialog.error(), HasSubstr("nothing.json: no such file"));
  EXPECT_TRUE(dialog.is_open());
  EXPECT_TRUE(dialog.choose("space.json"));
  EXPECT_EQ(taken, fs::canonical(dir / "space.json"));
  EXPECT_FALSE(dialog.is_open());
  // Saving takes a new name, but not in a folder that does not exist.
  dialog.open("Save the space", FileDialog::Mode::save, {".json"}, dir,
              [&](const fs::path& f) { taken = f; });
  EXPECT_FALSE(dialog.choose("no/such/new.json"));
  EXPECT_THAT(dialog.error(), HasSubstr("no such folder"));
  EXPECT_TRUE(dialog.choose((dir / "new.json").string()));
  EXPECT_EQ(taken, fs::weakly_canonical(dir / "new.json"));
}

// The dialog alone in a hidden window, driven as a person would: the mouse and keys written into
// ImGui's IO after the back end read the (unfocused, so absent) real ones. Each frame lasts 1/60 s
// of ImGui's time whatever it takes on llvmpipe, so that two presses two frames apart are a
// double-click (ImGui's limit: 0.30 s) and presses 30 frames apart never are.
struct DialogWindow {
  PanelWindow window{testing::hidden_window()};
  FileDialog& dialog;
  explicit DialogWindow(FileDialog& d) : dialog(d) {}
  void frame(const std::function<void(ImGuiIO&)>& input = {}) {
    window.begin_frame([&](ImGuiIO& io) {
      io.DeltaTime = 1.0f / 60.0f;
      if (input) input(io);
    });
    dialog.draw();
    window.end_frame();
  }
  void frames(int n) {
    for (int i = 0; i < n; ++i) frame();
  }
  // Presses and releases the left button on that entry `clicks` times, a frame each.
  void click(const std::string& entry, int clicks) {
    const auto at = dialog.entry_position(entry);
    ASSERT_TRUE(at.has_value()) << entry << " is not drawn";
    const ImVec2 p = *at;
    frame([&](ImGuiIO& io) { io.MousePos = p; });
    for (int i = 0; i < clicks; ++i) {
      frame([&](ImGuiIO& io) { io.MousePos = p, io.MouseDown[0] = true; });
      frame([&](ImGuiIO& io) { io.MousePos = p, io.MouseDown[0] = false; });
    }
    frames(30);  // half a second of ImGui's time: the next click starts afresh
  }
  void press(int key) {
    frame([&](ImGuiIO& io) { io.KeysDown[key] = true; });
    frame([&](ImGuiIO& io) { io.KeysDown[key] = false; });
  }
};

TEST(FileDialog, InAWindowAClickSelectsADoubleClickEntersAFolderOnceOrTakesAFile) {
  // sub/ is the first row here and inner/ the first row in sub: a double-click that entered on its
  // first click would enter inner/ with its second.
  const auto dir = fs::canonical(nibrig::test::scratch_dir("file_dialog_clicks"));
  fs::create_directories(dir / "sub" / "inner");
  touch(dir / "top.json");
  touch(dir / "sub" / "deep.json");
  std::vector<fs::path> taken;
  FileDialog dialog;
  DialogWindow w(dialog);
  dialog.open("Open a space", FileDialog::Mode::open, {".json"}, dir,
              [&](const fs::path& f) { taken.push_back(f); });
  w.frames(3);  // the modal appears and is laid out

  w.click("sub", 1);
  EXPECT_EQ(dialog.folder(), dir) << "a single click entered the folder";
  EXPECT_EQ(dialog.selection(), "sub");
  w.click("top.json", 1);
  EXPECT_EQ(dialog.selection(), "top.json");
  EXPECT_TRUE(taken.empty()) << "a single click took the file";
  EXPECT_TRUE(dialog.is_open());

  w.click("sub", 2);
  EXPECT_EQ(dialog.folder(), dir / "sub") << "a double-click entered other than exactly one level";
  EXPECT_EQ(dialog.selection(), "");
  EXPECT_TRUE(taken.empty());

  w.click("deep.json", 2);
  ASSERT_EQ(taken.size(), 1u) << "a double-click on a file took it other than once";
  EXPECT_EQ(taken[0], dir / "sub" / "deep.json");
  EXPECT_FALSE(dialog.is_open());
  w.frames(3);
  EXPECT_EQ(taken.size(), 1u);
}

TEST(FileDialog, InAWindowEnterTakesTheSelectedFileOrEntersTheSelectedFolder) {
  const auto dir = fs::canonical(nibrig::test::scratch_dir("file_dialog_enter"));
  fs::create_directories(dir / "sub");
  touch(dir / "top.json");
  touch(dir / "sub" / "deep.json");
  std::vector<fs::path> taken;
  FileDialog dialog;
  DialogWindow w(dialog);
  dialog.open("Open a space", FileDialog::Mode::open, {".json"}, dir,
              [&](const fs::path& f) { taken.push_back(f); });
  w.frames(3);

  w.click("sub", 1);
  w.press(GLFW_KEY_ENTER);
  EXPECT_EQ(dialog.folder(), dir / "sub") << "Enter on a selected folder did not enter it";
  EXPECT_TRUE(taken.empty());
  w.frames(3);
  w.click("deep.json", 1);
  EXPECT_TRUE(taken.empty());
  w.press(GLFW_KEY_ENTER);
  ASSERT_EQ(taken.size(), 1u) << "Enter on a selected file took it other than once";
  EXPECT_EQ(taken[0], dir / "sub" / "deep.json");
  EXPECT_FALSE(dialog.is_open());
}

// A hidden window and the panel in it, drawn until `done` or the deadline.
struct FilesSession {
  PanelWindow window{testing::hidden_window()};
  Panel panel;
  explicit FilesSession(PanelSetup setup) : panel(std::move(setup)) {}
  void frame(const std::function<void(ImGuiIO&)>& input = {}) {
    window.begin_frame(input);
    panel.draw();
    window.end_frame();
  }
  bool until(const std::function<bool()>& done,
             std::chrono::seconds limit = std::chrono::seconds(600)) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (!done() && std::chrono::steady_clock::now() < deadline) {
      frame();
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return done();
  }
};

// Eight catalog pairings, every triplet of them judged `repeats` times by an observer of a random
// `dims`-D space (seed for the space, seed + 1 for the answers), written as dir/judgments.csv.
const std::vector<std::string> kJudgedStimuli = {"vero1/office", "vero2/office", "vero4/office",
                                                 "DM851/office", "DM854/office", "DM951/office",
                                                 "cryon/office", "stab/office"};
void write_judgments(const fs::path& dir, Eigen::Index dims, int repeats, unsigned seed) {
  model::io::TripletSet judged;
  judged.stimuli = kJudgedStimuli;
  judged.triplets = model::space::testing::every_triplet_judged(
                        model::space::testing::random_truth(
                            dims, static_cast<Eigen::Index>(kJudgedStimuli.size()), seed),
                        repeats, seed + 1)
                        .triplets;
  model::io::write_triplet_csv(dir / "judgments.csv", judged);
}

TEST(PanelFiles, ASpaceFittedInTheWindowIsShownSavedAndOpenedAgain) {
  const auto dir = nibrig::test::scratch_dir("panel_fit");
  // Every triplet judged 8 times by an observer of a known 2-D space.
  write_judgments(dir, 2, 8, 21);
  const std::vector<std::string>& stimuli = kJudgedStimuli;

  PanelSetup setup;
  setup.space = testing::write_small_space(dir);
  FilesSession s(setup);
  ASSERT_TRUE(s.until([&] { return !s.panel.busy(); }));
  ASSERT_EQ(s.panel.space_view().scene().tools.size(), 3u);

  SpaceFitRequest request;
  request.judgments = dir / "judgments.csv";
  request.starts = 4;
  request.seed = 5;
  request.bootstrap = 10;
  s.panel.fit_space(request);
  EXPECT_TRUE(s.panel.busy());
  ASSERT_TRUE(s.until([&] { return !s.panel.busy(); }));
  ASSERT_TRUE(s.panel.error().empty()) << s.panel.error();
  // The space shown is the fit of those judgments with the catalog's descriptors: its eight judged
  // tools where fit_space puts them from the same starts, with their bootstrap regions, and every
  // other pairing of the catalog placed through the map the fit learnt.
  const auto in =
      model::space::read_space_inputs(dir / "judgments.csv", model::io::default_catalog(), 2, 1.0);
  model::space::FitOptions options;
  options.starts = 4;
  options.seed = 5;
  const auto reference = model::space::fit_space(in.problem, options);
  const auto& scene = s.panel.space_view().scene();
  std::size_t judged_tools = 0;
  for (const auto& t : scene.tools) {
    if (!t.judged) continue;
    ++judged_tools;
    const std::string name = t.choice.tool + "/" + t.choice.surface;
    const auto at = std::find(stimuli.begin(), stimuli.end(), name) - stimuli.begin();
    ASSERT_LT(at, 8) << name;
    EXPECT_EQ(t.region.mean, reference.coordinates.col(at)) << name;
    EXPECT_EQ(t.region.radius.size(), 2u) << name << " has no bootstrap region";
  }
  EXPECT_EQ(judged_tools, 8u);
  EXPECT_GT(scene.tools.size(), 8u) << "no other tool was placed from its descriptors";
  EXPECT_THAT(scene.title, HasSubstr("judgments.csv"));
  EXPECT_TRUE(s.panel.space_file().empty());  // not saved yet

  // Saved: the file holds that space, and the panel now names it.
  s.panel.save_space(dir / "fitted.json");
  ASSERT_TRUE(s.until([&] { return !s.panel.busy(); }));
  ASSERT_TRUE(s.panel.error().empty()) << s.panel.error();
  EXPECT_EQ(s.panel.space_file(), dir / "fitted.json");
  EXPECT_THAT(s.panel.notice(), HasSubstr("fitted.json"));
  const auto saved = model::space::read_space_file(dir / "fitted.json");
  EXPECT_TRUE(saved.coordinates.isApprox(reference.coordinates, 1e-12));
  EXPECT_EQ(saved.regions.size(), 8u);
  ASSERT_TRUE(saved.descriptor_map.has_value());

  // Opened again (after the small space): the same tools in the same places.
  s.panel.open_space(setup.space);
  ASSERT_TRUE(s.until([&] { return !s.panel.busy(); }));
  EXPECT_EQ(s.panel.space_view().scene().tools.size(), 3u);
  s.panel.open_space(dir / "fitted.json");
  ASSERT_TRUE(s.until([&] { return !s.panel.busy(); }));
  EXPECT_EQ(s.panel.space_view().scene().tools.size(), scene.tools.size());

  // A fit of a file that is not judgments says so, naming it, and the space stays.
  touch(dir / "not_judgments.csv");
  request.judgments = dir / "not_judgments.csv";
  s.panel.fit_space(request);
  ASSERT_TRUE(s.until([&] { return !s.panel.busy(); }));
  EXPECT_THAT(s.panel.error(), HasSubstr("not_judgments.csv"));
}

TEST(PanelFiles, AFitInTheWindowJudgesByTheModelAskedOrChosenAndTheViewSaysWhich) {
  const auto dir = nibrig::test::scratch_dir("panel_fit_model");
  write_judgments(dir, 1, 6, 31);  // every triplet judged 6 times by an observer of a 1-D space
  PanelSetup setup;
  setup.space = testing::write_small_space(dir);
  FilesSession s(setup);
  ASSERT_TRUE(s.until([&] { return !s.panel.busy(); }));

  // A model given: a noise per stimulus, which each judged tool's tooltip shows as its sigma.
  SpaceFitRequest request;
  request.judgments = dir / "judgments.csv";
  request.descriptors = false;
  request.dims = 1;
  request.starts = 2;
  request.bootstrap = 0;
  request.model = "logistic+noise";
  s.panel.fit_space(request);
  ASSERT_TRUE(s.until([&] { return !s.panel.busy(); }));
  ASSERT_TRUE(s.panel.error().empty()) << s.panel.error();
  const auto& given = s.panel.space_view().scene();
  EXPECT_THAT(given.judgment_model, HasSubstr("logistic+noise, noise per stimulus"));
  EXPECT_THAT(given.model_reason, HasSubstr("given"));
  ASSERT_EQ(given.tools.size(), 8u);
  for (const auto& t : given.tools) {
    ASSERT_TRUE(t.noise_sigma.has_value()) << t.label;
    EXPECT_GT(*t.noise_sigma, 0.0) << t.label;
  }

  // "auto": the family cross-validation chooses from the same folds as choose_model's own, with
  // every candidate's score kept in the space the panel would save.
  request.model = "auto";
  s.panel.fit_space(request);
  ASSERT_TRUE(s.until([&] { return !s.panel.busy(); }));
  ASSERT_TRUE(s.panel.error().empty()) << s.panel.error();
  const auto in = model::space::read_space_inputs(dir / "judgments.csv", {}, 1, 0.0);
  model::space::ModelChoiceOptions choice;
  choice.cross_validation.folds = 5;
  choice.cross_validation.seed = 1;
  choice.cross_validation.fit.starts = 2;
  choice.cross_validation.fit.seed = 1;
  const auto reference = model::space::choose_model(in.problem, choice);
  const auto& chosen = s.panel.space_view().scene();
  EXPECT_THAT(chosen.judgment_model,
              ::testing::StartsWith(model::space::family_name(reference.chosen)));
  EXPECT_EQ(chosen.model_reason, reference.reason);
  s.panel.save_space(dir / "auto.json");
  ASSERT_TRUE(s.until([&] { return !s.panel.busy(); }));
  EXPECT_EQ(model::space::read_space_file(dir / "auto.json").model_scores.size(), 12u);
}

TEST(PanelFiles, ACatalogThatCannotBeReadChangesNothingAndOneThatCanIsUsed) {
  const auto dir = nibrig::test::scratch_dir("panel_catalog");
  PanelSetup setup;
  setup.space = testing::write_small_space(dir);
  FilesSession s(setup);
  ASSERT_TRUE(s.until([&] { return !s.panel.busy(); }));
  std::ofstream(dir / "broken.json") << R"({"format": "nibrig-catalog", "version": 1, "tools": [)";
  s.panel.open_catalog(dir / "broken.json");
  ASSERT_TRUE(s.until([&] { return !s.panel.busy(); }));
  EXPECT_THAT(s.panel.error(), HasSubstr("broken.json"));
  EXPECT_TRUE(s.panel.catalog_file().empty());
  EXPECT_EQ(s.panel.space_view().scene().tools.size(), 3u);

  fs::copy_file(model::io::default_catalog(), dir / "catalog.json");
  s.panel.open_catalog(dir / "catalog.json");
  ASSERT_TRUE(s.until([&] { return !s.panel.busy(); }));
  EXPECT_TRUE(s.panel.error().empty()) << s.panel.error();
  EXPECT_EQ(s.panel.catalog_file(), dir / "catalog.json");
  EXPECT_THAT(s.panel.notice(), HasSubstr("catalog.json"));
  EXPECT_EQ(s.panel.space_view().scene().tools.size(), 3u);  // the space's tools placed again
  EXPECT_EQ(s.panel.audio().catalog().pairings.size(),
            model::io::read_catalog(dir / "catalog.json").pairings.size());

  // A forcing model that is not one is refused the same way.
  s.panel.open_forcing(dir / "broken.json");
  ASSERT_TRUE(s.until([&] { return !s.panel.busy(); }));
  EXPECT_THAT(s.panel.error(), HasSubstr("broken.json"));
  EXPECT_TRUE(s.panel.forcing_file().empty());
}

TEST(PanelFiles, AForcingModelTheLabStoredIsOpenedByItsName) {
  const auto dir = nibrig::test::scratch_dir("panel_stored_forcing");
  const nibrig::test::ScopedEnvironment store("NIBRIG_FORCING_MODELS", (dir / "store").string());
  const auto kept = model::forcing::save_forcing_model("lab-pla", model::design::hand_made_model());
  ASSERT_EQ(model::forcing::stored_forcing_models(), std::vector<std::string>{"lab-pla"});
  PanelSetup setup;
  setup.space = testing::write_small_space(dir);
  FilesSession s(setup);
  ASSERT_TRUE(s.until([&] { return !s.panel.busy(); }));
  s.panel.open_stored_forcing("lab-pla");
  ASSERT_TRUE(s.until([&] { return !s.panel.busy(); }));
  EXPECT_TRUE(s.panel.error().empty()) << s.panel.error();
  EXPECT_EQ(s.panel.forcing_file(), kept);
  // A name the store does not hold changes nothing and says what it holds.
  s.panel.open_stored_forcing("lab-petg");
  ASSERT_TRUE(s.until([&] { return !s.panel.busy(); }));
  EXPECT_THAT(s.panel.error(), HasSubstr("stored: lab-pla"));
  EXPECT_EQ(s.panel.forcing_file(), kept);
}

TEST(PanelKeys, CtrlNumbersShowViewsAndLettersSwitchTheComparedTools) {
  const auto dir = nibrig::test::scratch_dir("panel_keys");
  PanelSetup setup;
  setup.space = testing::write_small_space(dir);
  FilesSession s(setup);
  ASSERT_TRUE(s.until([&] { return !s.panel.busy(); }));
  const auto press = [&](int key, bool ctrl) {
    s.frame([&](ImGuiIO& io) { io.KeysDown[key] = true, io.KeyCtrl = ctrl; });
    s.frame([&](ImGuiIO& io) { io.KeysDown[key] = false, io.KeyCtrl = false; });
  };
  press(GLFW_KEY_2, true);
  s.frame();
  EXPECT_EQ(s.panel.current(), View::design);
  press(GLFW_KEY_5, true);
  s.frame();
  EXPECT_EQ(s.panel.current(), View::devices);
  press(GLFW_KEY_1, true);
  s.frame();
  EXPECT_EQ(s.panel.current(), View::space);

  // Two tools compared (no device: the engine runs all the same); B switches to the second, A back.
  s.panel.audio().play({{"cryon", "office"}, {"stab", "office"}});
  ASSERT_TRUE(s.until([&] { return !s.panel.audio().making_sounds(); }));
  ASSERT_EQ(s.panel.audio().playing().size(), 2u) << s.panel.audio().error();
  EXPECT_EQ(s.panel.audio().audition().selected(), 0u);
  press(GLFW_KEY_B, false);
  EXPECT_EQ(s.panel.audio().audition().selected(), 1u);
  press(GLFW_KEY_A, false);
  EXPECT_EQ(s.panel.audio().audition().selected(), 0u);
  press(GLFW_KEY_C, false);  // there is no third: nothing changes
  EXPECT_EQ(s.panel.audio().audition().selected(), 0u);
  press(GLFW_KEY_SPACE, false);
  EXPECT_EQ(s.panel.audio().stroke_description(), "stopped");
  EXPECT_FALSE(s.panel.audio().sounding().has_value());
}

}  // namespace
}  // namespace nibrig::ui::panel
