#include "model/study/study_report.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <map>

#include "model/io/atomic_file.hpp"
#include "model/io/job_files.hpp"
#include "model/space/simulated_observer.hpp"
#include "model/space/space_file.hpp"
#include "model/space/synthetic_study.hpp"
#include "tests/model/study/study_test_support.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::study {
namespace {

StudySettings simulated_session(const std::filesystem::path& study, const std::string& id) {
  StudySettings s;
  s.study = study;
  s.participant = id;
  s.respondent = "simulated";
  return s;
}

// The fitted coordinates in the study's stimulus order (a fit numbers stimuli as its judgments
// file first names them).
Eigen::MatrixXd in_study_order(const space::SpaceFile& space, const StudyDefinition& d) {
  Eigen::MatrixXd out(space.coordinates.rows(), static_cast<Eigen::Index>(d.stimuli.size()));
  for (std::size_t i = 0; i < d.stimuli.size(); ++i) {
    const auto it = std::find(space.stimuli.begin(), space.stimuli.end(), d.stimuli[i].name);
    EXPECT_NE(it, space.stimuli.end()) << d.stimuli[i].name;
    out.col(static_cast<Eigen::Index>(i)) =
        space.coordinates.col(static_cast<Eigen::Index>(it - space.stimuli.begin()));
  }
  return out;
}

TEST(StudyReport, ATwoStageRunWithASimulatedParticipantRecoversItsSpaceAsTheSyntheticStudyDoes) {
  // The reference: `space synth`'s recovery for the same size (15 stimuli, 2-D, the paper's plan
  // and data selection), over 12 random truths.
  space::SyntheticStudyOptions synth;
  synth.trials = 12;
  synth.dims = {2};
  synth.stimuli = 15;
  synth.seed = 3;
  const space::DimensionRecovery reference = space::run_synthetic_study(synth).front();

  // The runner: a truth of the same kind, one participant answering from it through the whole
  // two-stage session, the report's fit.
  std::mt19937_64 generator(77);
  const Eigen::MatrixXd truth = space::random_space(2, 15, generator);
  const auto dir = nibrig::test::scratch_dir("report_recovery");
  const StudyDefinition d = test::definition_of(15);
  const auto study = test::make_study(dir, d);
  SimulatedParticipant participant(truth, {}, 4);
  NothingPresented nothing;
  ASSERT_TRUE(run_study(simulated_session(study, "S01"), nothing, participant).complete);
  StudyReportSettings settings;
  settings.bootstrap = 20;
  const StudyReport report = report_study(study, dir / "report", settings);
  ASSERT_TRUE(report.fitted);
  EXPECT_FALSE(report.with_descriptors) << "made-up tools have no descriptors";
  const space::RecoveryError runner = space::recovery_error(in_study_order(report.fitted->file, d), truth);
  std::printf("recovery: runner coordinates %.3f probabilities %.3f; synth %.3f ± %.3f, %.3f ± %.3f\n",
              runner.coordinates, runner.probabilities, reference.coordinate_error.mean,
              reference.coordinate_error.sd, reference.probability_error.mean,
              reference.probability_error.sd);
  // One truth against the spread of twelve: within three standard deviations of their mean.
  EXPECT_LT(runner.coordinates,
            reference.coordinate_error.mean + 3 * reference.coordinate_error.sd);
  EXPECT_LT(runner.probabilities,
            reference.probability_error.mean + 3 * reference.probability_error.sd);
  // The files the report promises, and the participant's agreement with the space they built.
  EXPECT_TRUE(std::filesystem::exists(dir / "report" / kReportJudgments));
  EXPECT_TRUE(std::filesystem::exists(dir / "report" / kReportSpace));
  EXPECT_TRUE(std::filesystem::exists(dir / "report" / kReportStatistics));
  ASSERT_EQ(report.participants.size(), 1u);
  EXPECT_FALSE(report.participants[0].with_others) << "alone in the study";
  // Answers drawn from the truth agree with the fitted prediction as often as with the truth's
  // own: the mean of max(p, 1−p) over the answered trials, to 3 points.
  const space::SimulatedObserver observer(truth);
  double expected = 0.0, n = 0.0;
  for (const auto& r : report.study.participants[0].responses) {
    if (r.practice) continue;
    const double p = observer.probability_first(r.planned.reference, r.planned.left, r.planned.right);
    expected += std::max(p, 1.0 - p);
    n += 1.0;
  }
  EXPECT_NEAR(report.participants[0].with_space.fraction, expected / n, 0.03);
}

// A validation study of six stimuli in a random 2-D space (drawn with `space_seed`), answered by
// `participants` simulated participants (seeds from `first_seed`), and the space they answer from.
struct ValidationStudy {
  ValidationStudy(const std::filesystem::path& dir, unsigned space_seed, int participants, std::uint64_t first_seed) {
    std::mt19937_64 generator(space_seed);
    truth = space::random_space(2, 6, generator);
    StudyDefinition d = test::definition_of(6);
    d.mode = StudyMode::validation;
    d.practice = 0;
    folder = test::make_study(dir, d);
    for (const auto& s : d.stimuli) space.stimuli.push_back(s.name);
    space.coordinates = truth;
    space.model.scale = space::kThurstoneScale;
    NothingPresented nothing;
    for (int k = 0; k < participants; ++k) {
      SimulatedParticipant p(truth, {}, first_seed + static_cast<std::uint64_t>(k));
      run_study(simulated_session(folder, "V" + std::to_string(k)), nothing, p);
    }
  }
  Eigen::MatrixXd truth;
  std::filesystem::path folder;
  space::SpaceFile space;
};

TEST(StudyReport, AValidationStudyGivesThePapersStatisticsAgainstTheSpace) {
  // Sec. 6.1: designs judged against a reference by 12 participants, scored against the space
  // they answer from. The majority agreement is counted here from the logs, independently.
  const auto dir = nibrig::test::scratch_dir("report_validation");
  const ValidationStudy v(dir, 5, 12, 100);
  const Eigen::MatrixXd& truth = v.truth;
  const auto& study = v.folder;
  space::write_space_file(dir / "truth.json", v.space);
  StudyReportSettings settings;
  EXPECT_THROW(report_study(study, dir / "report", settings), std::invalid_argument)
      << "a validation study needs its space";
  settings.validation_space = dir / "truth.json";
  const StudyReport report = report_study(study, dir / "report", settings);
  ASSERT_TRUE(report.validation);
  EXPECT_FALSE(report.fitted);
  ASSERT_EQ(report.validation_triplets.size(), 10u);  // the pairs of 5 candidates
  const space::SimulatedObserver observer(truth);
  double agree = 0.0, decided = 0.0;
  for (const auto& t : report.validation_triplets) {
    EXPECT_EQ(t.count_a + t.count_b, 12);
    if (t.count_a == t.count_b) continue;
    decided += 1.0;
    agree += (observer.probability_first(t.reference, t.a, t.b) > 0.5) == (t.count_a > t.count_b);
  }
  EXPECT_DOUBLE_EQ(report.validation->majority.trials, decided);
  EXPECT_DOUBLE_EQ(report.validation->majority.agreements, agree);
  ASSERT_EQ(report.participants.size(), 12u);
  for (const auto& p : report.participants) {
    ASSERT_TRUE(p.with_others);
    EXPECT_EQ(p.with_others->trials, 10.0);
    EXPECT_EQ(p.answers, 10u);
  }
}

// A space named among the report's own outputs is read before anything is written, and the job's
// check refuses replacing it; a space given to a study that is not a validation one is refused,
// not ignored (the trial's `report -o out --space out/space.json` had overwritten it).
TEST(StudyReport, AGivenSpaceIsNeverReplacedByTheReportItScores) {
  const auto dir = nibrig::test::scratch_dir("report_keeps_space");
  const ValidationStudy v(dir, 6, 3, 200);
  const Eigen::MatrixXd& truth = v.truth;
  const auto& study = v.folder;
  const space::SpaceFile& space = v.space;
  NothingPresented nothing;
  const auto bytes = [](const std::filesystem::path& f) {
    std::ifstream in(f, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  for (const char* name : {kReportJudgments, kReportStatistics}) {
    SCOPED_TRACE(name);
    const auto out = dir / (std::string("out_") + name);
    std::filesystem::create_directories(out);
    space::write_space_file(out / name, space);
    const std::string before = bytes(out / name);
    const io::JobFiles job;  // as a face opens one for the command or the Python call
    StudyReportSettings settings;
    settings.validation_space = out / name;
    EXPECT_THROW(report_study(study, out, settings), io::OutputFileError);
    EXPECT_EQ(bytes(out / name), before);
  }

  StudyDefinition a = test::definition_of(6);
  a.practice = 0;
  const auto actuator = test::make_study(dir / "actuator", a);
  SimulatedParticipant p(truth, {}, 300);
  run_study(simulated_session(actuator, "A1"), nothing, p);
  space::write_space_file(dir / "space.json", space);
  StudyReportSettings settings;
  settings.validation_space = dir / "space.json";
  try {
    report_study(actuator, dir, settings);
    ADD_FAILURE() << "a space given to a study that does not validate was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find((dir / "space.json").string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("validation study only"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir / kReportJudgments)) << "refused before anything was written";
}

}  // namespace
}  // namespace nibrig::model::study

namespace nibrig::model::study {
namespace {

TEST(SimulatedTruth, JudgedStimuliKeepTheirPlaceAndOthersGoWhereTheCallerPlacesThem) {
  // A design point is neither judged nor in the catalog: the face predicts it (here a fixed
  // place), and a stimulus nobody can place is refused naming it.
  space::SpaceFile space;
  space.stimuli = {"a/x", "b/x", "c/x"};
  space.coordinates = Eigen::MatrixXd{{0.0, 1.0, 2.0}, {0.5, -0.5, 0.0}};
  space.model.scale = space::kThurstoneScale;
  const std::vector<Stimulus> stimuli = {{"c/x", "c", "x"}, {"D1", "DM85:1,tip=2mm", "x"}, {"a/x", "a", "x"}};
  const PlaceOther place = [](const Stimulus& s) -> std::optional<Eigen::VectorXd> {
    if (s.name != "D1") return std::nullopt;
    return Eigen::Vector2d{7.0, 8.0};
  };
  const Eigen::MatrixXd truth = truth_for_stimuli(space, "space.json", stimuli, "", place);
  EXPECT_EQ(truth.col(0), space.coordinates.col(2));
  EXPECT_EQ(truth.col(1), Eigen::Vector2d(7.0, 8.0));
  EXPECT_EQ(truth.col(2), space.coordinates.col(0));
  try {
    truth_for_stimuli(space, "space.json", stimuli, "");
    ADD_FAILURE() << "an unplaceable stimulus was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'D1'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace nibrig::model::study
