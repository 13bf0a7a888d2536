// End-to-end tests of `nibrig experiment run|report`, in the forms a user types: a simulated
// participant through a whole two-stage study on the actuator and on the simulated rig (recovering
// its space as `space synth` does for the same size), a run killed with SIGKILL and resumed, a
// person's keys at the terminal on a real JACK server, and the input refused before anyone starts.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <fstream>
#include <random>
#include <thread>

#include "model/io/bundled_assets.hpp"
#include "model/io/catalog_file.hpp"
#include "model/space/simulated_observer.hpp"
#include "model/space/space_file.hpp"
#include "model/space/synthetic_study.hpp"
#include "model/study/study_results.hpp"
#include "tests/support/jack_server.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/ui/cli/cli_harness.hpp"

namespace nibrig::ui::cli {
namespace {

using test::run_cli;
namespace fs = std::filesystem;

// `count` catalog pairings with a vibration spectrum (so the actuator can play them) and friction
// (so the report ties the space to their descriptors), drawn with `seed`, written one a line; and a
// random 2-D truth over them as a space file.
struct ExperimentTruth {
  fs::path stimuli, space;
  Eigen::MatrixXd coordinates;
  std::vector<std::string> names;
};

ExperimentTruth make_truth(const fs::path& dir, std::size_t count, std::uint64_t seed) {
  const auto catalog = model::io::read_catalog(model::io::default_catalog());
  std::vector<std::string> playable;
  for (const auto& p : catalog.pairings)
    if (p.vibration && p.friction) playable.push_back(p.tool + "/" + p.surface);
  std::mt19937_64 generator(seed);
  std::shuffle(playable.begin(), playable.end(), generator);
  ExperimentTruth t;
  t.names.assign(playable.begin(), playable.begin() + static_cast<std::ptrdiff_t>(count));
  t.stimuli = dir / "stimuli.txt";
  std::ofstream list(t.stimuli);
  for (const auto& n : t.names) list << n << "\n";
  t.coordinates = model::space::random_space(2, count, generator);
  model::space::SpaceFile space;
  space.stimuli = t.names;
  space.coordinates = t.coordinates;
  space.model.scale = model::space::kThurstoneScale;
  t.space = dir / "truth.json";
  model::space::write_space_file(t.space, space);
  return t;
}

// The report's space in the truth's stimulus order.
Eigen::MatrixXd fitted_in_order(const fs::path& space_file, const std::vector<std::string>& names) {
  const auto space = model::space::read_space_file(space_file);
  Eigen::MatrixXd out(space.coordinates.rows(), static_cast<Eigen::Index>(names.size()));
  for (std::size_t i = 0; i < names.size(); ++i) {
    const auto it = std::find(space.stimuli.begin(), space.stimuli.end(), names[i]);
    EXPECT_NE(it, space.stimuli.end()) << names[i];
    out.col(static_cast<Eigen::Index>(i)) =
        space.coordinates.col(static_cast<Eigen::Index>(it - space.stimuli.begin()));
  }
  return out;
}

// `space synth`'s recovery for the same size, over 12 random truths: what the run is held to.
model::space::DimensionRecovery synth_reference(std::size_t stimuli, std::size_t budget,
                                                model::space::FitData data) {
  model::space::SyntheticStudyOptions o;
  o.trials = 12;
  o.dims = {2};
  o.stimuli = stimuli;
  o.seed = 9;
  if (budget > 0) o.design = model::space::two_stage_for_budget(stimuli, budget);
  o.design.fit_data = data;
  return model::space::run_synthetic_study(o).front();
}

void expect_recovered(const ExperimentTruth& truth, const fs::path& report, std::size_t budget,
                      model::space::FitData data) {
  const auto reference = synth_reference(truth.names.size(), budget, data);
  const auto error = model::space::recovery_error(fitted_in_order(report / "space.json", truth.names),
                                                  truth.coordinates);
  std::printf("recovered to %.3f (coordinates) and %.3f (probabilities); space synth: %.3f ± %.3f "
              "and %.3f ± %.3f\n",
              error.coordinates, error.probabilities, reference.coordinate_error.mean,
              reference.coordinate_error.sd, reference.probability_error.mean,
              reference.probability_error.sd);
  // One truth against twelve: within three of their standard deviations of their mean.
  EXPECT_LT(error.coordinates, reference.coordinate_error.mean + 3 * reference.coordinate_error.sd);
  EXPECT_LT(error.probabilities,
            reference.probability_error.mean + 3 * reference.probability_error.sd);
}

TEST(ExperimentCli, ASimulatedParticipantsTwoStageRunOnTheActuatorRecoversItsSpace) {
  const auto dir = nibrig::test::scratch_dir("cli_experiment_actuator");
  const ExperimentTruth truth = make_truth(dir, 15, 1);
  ::testing::internal::CaptureStdout();
  ASSERT_EQ(run_cli({"experiment", "run", "--stimuli", truth.stimuli.string(), "--mode", "actuator",
                     "--participant", "P01", "--simulate", truth.space.string(), "--seed", "5",
                     "-o", (dir / "study").string()}),
            0);
  ASSERT_EQ(run_cli({"experiment", "report", (dir / "study").string(), "-o",
                     (dir / "report").string(), "--bootstrap", "20"}),
            0);
  const std::string out = ::testing::internal::GetCapturedStdout();
  // The two-stage plan of 15 stimuli for seed 5: 1966 trials and 3 of practice, all answered.
  const auto report = test::read_json(dir / "report" / "report.json");
  ASSERT_EQ(report["participants"].size(), 1u) << out;
  EXPECT_EQ(report["participants"][0]["id"], "P01");
  EXPECT_EQ(report["participants"][0]["answers"].get<int>() +
                report["participants"][0]["practice"].get<int>(),
            1969);
  for (const char* f : {"judgments.csv", "space.json", "report.json"})
    EXPECT_TRUE(fs::exists(dir / "report" / f)) << f;
  EXPECT_TRUE(test::is_png(dir / "report" / "space.png"));
  EXPECT_TRUE(test::is_png(dir / "report" / "agreement.png"));
  expect_recovered(truth, dir / "report", 0, model::space::FitData::paper);
  // Catalog pairings: the space is tied to their descriptors and can place other tools.
  EXPECT_TRUE(model::space::read_space_file(dir / "report" / "space.json").descriptor_map.has_value());
  // The judgments are the CSV `space fit` reads, with the participant as observer.
  const auto judgments = model::io::read_triplet_csv(dir / "report" / "judgments.csv");
  EXPECT_EQ(judgments.triplets.front().observer, "P01");
}

TEST(ExperimentCli, ASimulatedParticipantOnTheSimulatedRigRecoversItsSpaceToo) {
  // Each play runs the study's 3 s sweep on a simulated rig (with --simulate as fast as it
  // computes, about 35 ms in Release): a smaller study keeps it to a minute under the sanitizers.
  const auto dir = nibrig::test::scratch_dir("cli_experiment_rig");
  const ExperimentTruth truth = make_truth(dir, 6, 2);
  ::testing::internal::CaptureStdout();
  ASSERT_EQ(run_cli({"experiment", "run", "--stimuli", truth.stimuli.string(), "--mode", "rig",
                     "--simulated-rig", "--trials", "100", "--practice", "0",
                     "--participant", "P01", "--simulate", truth.space.string(), "-o",
                     (dir / "study").string()}),
            0);
  // Every answer: at this size the paper's selection (unanimous stage-one triplets only) leaves
  // some truths' fits without a bound (space synth: coordinate errors in the hundreds).
  ASSERT_EQ(run_cli({"experiment", "report", (dir / "study").string(), "--bootstrap", "0",
                     "--all-judgments"}),
            0);
  const std::string out = ::testing::internal::GetCapturedStdout();
  EXPECT_NE(out.find("operator: mount "), std::string::npos) << "the operator is told what to mount";
  expect_recovered(truth, dir / "study" / "report", 100, model::space::FitData::all_judgments);
}

TEST(ExperimentCli, AValidationStudyReportsThePapersStatisticsAgainstTheSpace) {
  // Sec. 6.1: designs (here catalog pairings) judged against a reference by several participants,
  // scored against the space they answer from: its majority must agree far above chance.
  const auto dir = nibrig::test::scratch_dir("cli_experiment_validation");
  const ExperimentTruth truth = make_truth(dir, 7, 6);
  ::testing::internal::CaptureStdout();
  for (const char* id : {"V1", "V2", "V3", "V4", "V5"})
    ASSERT_EQ(run_cli({"experiment", "run", "--stimuli", truth.stimuli.string(), "--mode",
                       "validation", "--practice", "0", "--participant", id, "--simulate",
                       truth.space.string(), "-o", (dir / "study").string()}),
              0);
  ASSERT_EQ(run_cli({"experiment", "report", (dir / "study").string(), "--space", truth.space.string()}), 0);
  const std::string out = ::testing::internal::GetCapturedStdout();
  EXPECT_TRUE(test::is_png(dir / "study" / "report" / "validation.png"));
  const auto report = test::read_json(dir / "study" / "report" / "report.json");
  EXPECT_EQ(report["validation"]["triplets"].size(), 15u);  // the pairs of 6 candidates
  // Five answers from the truth per triplet: the majority follows the truth's preference except
  // where that is near a coin toss; against chance (50 %) the z-test is far in the tail.
  EXPECT_GT(report["validation"]["majority_agreement"]["fraction"].get<double>(), 0.7);
  EXPECT_LT(report["validation"]["majority_agreement"]["p_value"].get<double>(), 0.05);
  EXPECT_EQ(report["participants"].size(), 5u);
}

TEST(ExperimentCli, KilledWithSigkillMidRunAndResumedWritesTheSameJudgments) {
  const auto dir = nibrig::test::scratch_dir("cli_experiment_kill");
  const ExperimentTruth truth = make_truth(dir, 8, 3);
  const std::vector<std::string> common = {"experiment", "run", "--stimuli", truth.stimuli.string(),
                                           "--participant", "P07", "--simulate", truth.space.string()};
  auto with = [&](std::vector<std::string> more) {
    std::vector<std::string> args = common;
    args.insert(args.end(), more.begin(), more.end());
    return args;
  };
  ::testing::internal::CaptureStdout();
  ASSERT_EQ(run_cli(with({"-o", (dir / "whole").string()})), 0);
  // Paced at 200× its modelled times (5-10 s a trial): 25-50 ms a trial, killed at a random
  // moment of the 1.5 s after its first answer is on disk (under the sanitizers on a busy machine
  // the command needs seconds before it: a kill before it would test nothing).
  const pid_t pid = test::start_cli(with({"--pace", "200", "-o", (dir / "killed").string()}));
  const fs::path log = dir / "killed" / "participants" / "P07" / "responses.csv";
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::minutes(2);
  while (!(fs::exists(log) && fs::file_size(log) > 100) && std::chrono::steady_clock::now() < give_up)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  std::random_device entropy;
  const auto wait = std::chrono::milliseconds(entropy() % 1500);
  SCOPED_TRACE("killed " + std::to_string(wait.count()) + " ms after the first answer");
  std::this_thread::sleep_for(wait);
  ASSERT_EQ(kill(pid, SIGKILL), 0);
  EXPECT_EQ(test::wait_cli(pid), 128 + SIGKILL);
  const auto partial = model::study::read_study(dir / "killed");
  ASSERT_EQ(partial.participants.size(), 1u);
  const std::size_t answered = partial.participants[0].responses.size();
  EXPECT_GT(answered, 0u);
  ASSERT_EQ(run_cli({"experiment", "run", "--participant", "P07", "--simulate",
                     truth.space.string(), "--resume", "-o", (dir / "killed").string()}),
            0);
  for (const char* study : {"whole", "killed"})
    ASSERT_EQ(run_cli({"experiment", "report", (dir / study).string(), "--bootstrap", "0"}), 0);
  ::testing::internal::GetCapturedStdout();
  std::ifstream a(dir / "whole" / "report" / "judgments.csv"), b(dir / "killed" / "report" / "judgments.csv");
  const std::string whole((std::istreambuf_iterator<char>(a)), std::istreambuf_iterator<char>());
  const std::string killed((std::istreambuf_iterator<char>(b)), std::istreambuf_iterator<char>());
  EXPECT_FALSE(whole.empty());
  EXPECT_EQ(whole, killed) << answered << " answers were on disk at the kill";
}

TEST(ExperimentCli, APersonAnswersWithKeysAtTheTerminalWhileTheActuatorPlaysOnJack) {
  nibrig::testing::JackServer server;
  const auto dir = nibrig::test::scratch_dir("cli_experiment_terminal");
  // A named stimulus too (a design point would be named the same way; predicting one takes
  // minutes under the sanitizers, and the list's parsing is tested in model/study).
  std::ofstream(dir / "stimuli.txt") << "cryon/office\nstab/office\nD1 = vero2/office\n";
  // Two listed trials (`space plan`'s format), no practice.
  std::ofstream(dir / "plan.csv") << "trial,stage,reference,left,right\n1,1,cryon/office,stab/office,D1\n"
                                     "2,1,stab/office,D1,cryon/office\n";
  // Consent, then: an answer refused before all three were felt, plays, answers; Enter is ignored.
  std::ofstream(dir / "keys.txt") << "y\n1\nr\na\nb\na\n1\n\nb\nr\na\nb\n2\n";
  ::testing::internal::CaptureStdout();
  const pid_t pid = test::start_cli(
      {"experiment", "run", "--stimuli", (dir / "stimuli.txt").string(), "--plan",
       (dir / "plan.csv").string(), "--practice", "0", "--participant", "P01", "--api", "jack",
       "--device", "system", "-o", (dir / "study").string()},
      dir / "keys.txt");
  ASSERT_EQ(test::wait_cli(pid), 0);
  const std::string out = ::testing::internal::GetCapturedStdout();
  EXPECT_NE(out.find("feel the reference, A and B first"), std::string::npos) << out;
  EXPECT_NE(out.find("playing on jack"), std::string::npos) << out;
  const auto study = model::study::read_study(dir / "study");
  ASSERT_EQ(study.participants.size(), 1u);
  const auto& r = study.participants[0].responses;
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0].plays, "RABA");
  EXPECT_EQ(r[0].chosen, model::space::Choice::left);
  EXPECT_EQ(r[1].plays, "BRAB");
  EXPECT_EQ(r[1].chosen, model::space::Choice::right);
  EXPECT_EQ(study.definition.stimuli[2].name, "D1");
  EXPECT_EQ(study.definition.stimuli[2].tool, "vero2");
}

TEST(ExperimentCli, BadInputIsRefusedBeforeAParticipantStarts) {
  const auto dir = nibrig::test::scratch_dir("cli_experiment_bad");
  const ExperimentTruth truth = make_truth(dir, 4, 4);
  std::ofstream(dir / "unknown_tool.txt") << "cryon/office\nquill/office\nstab/office\n";
  std::ofstream(dir / "unknown_surface.txt") << "cryon/office\ncryon/slate\nstab/office\n";
  std::ofstream(dir / "two.txt") << "cryon/office\nstab/office\n";
  // A name that is not UTF-8 (Latin-1 'é'): the trial got a raw json.exception after the fit and
  // a half-made study folder.
  std::ofstream(dir / "latin1.txt") << "cryon/office\nstab/office\ncaf\xE9/office\n";
  struct Case {
    std::vector<std::string> args;
    int code;
    std::string says;
  };
  const std::string study = (dir / "study").string();
  const std::vector<Case> cases = {
      {{"--stimuli", (dir / "unknown_tool.txt").string(), "--simulate", truth.space.string()}, 1,
       "stimulus 'quill/office'"},
      {{"--stimuli", (dir / "unknown_surface.txt").string(), "--simulate", truth.space.string()}, 1,
       "stimulus 'cryon/slate'"},
      {{"--stimuli", (dir / "two.txt").string(), "--simulate", truth.space.string()}, 1,
       "expected at least 3 stimuli"},
      {{"--stimuli", (dir / "latin1.txt").string(), "--simulate", truth.space.string()}, 1,
       "latin1.txt line 3: byte 4 is not UTF-8 text"},
      // No audio device by that name (or no server at all): refused before the study is made.
      {{"--stimuli", truth.stimuli.string(), "--api", "jack", "--device", "no-such-device"}, 1, "jack"},
      {{"--stimuli", truth.stimuli.string(), "--mode", "rig", "--simulate", truth.space.string()}, 2,
       "--simulated-rig"},
      {{"--simulate", truth.space.string()}, 2, "a new study needs its stimulus list"},
  };
  for (const auto& c : cases) {
    std::vector<std::string> args = {"experiment", "run", "--participant", "P01", "-o", study};
    args.insert(args.end(), c.args.begin(), c.args.end());
    ::testing::internal::CaptureStderr();
    EXPECT_EQ(run_cli(args), c.code) << c.says;
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find(c.says), std::string::npos) << err;
    EXPECT_FALSE(fs::exists(dir / "study" / "participants" / "P01")) << c.says;
    EXPECT_FALSE(fs::exists(dir / "study")) << c.says << ": a refused run leaves no study folder";
  }
  // A participant ID already taken asks for --resume or a new ID, and nothing is appended.
  ::testing::internal::CaptureStdout();
  ASSERT_EQ(run_cli({"experiment", "run", "--stimuli", truth.stimuli.string(), "--participant",
                     "P01", "--simulate", truth.space.string(), "--trials", "10", "-o", study}),
            0);
  ::testing::internal::GetCapturedStdout();
  const auto before = fs::file_size(dir / "study" / "participants" / "P01" / "responses.csv");
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(run_cli({"experiment", "run", "--stimuli", truth.stimuli.string(), "--participant",
                     "P01", "--simulate", truth.space.string(), "--trials", "10", "-o", study}),
            2);
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(err.find("--resume, or give a new participant ID"), std::string::npos) << err;
  EXPECT_EQ(fs::file_size(dir / "study" / "participants" / "P01" / "responses.csv"), before);
}

}  // namespace
}  // namespace nibrig::ui::cli
