// Starting a study's session, as every face does it: each refusal names the part of the request
// at fault and leaves the disk as it was; a start is ready however the stimuli are felt (nothing
// presented, the simulated rig with its operator, the actuator's audition on a real JACK server); a second
// participant joins the folder with its texts as the experimenter edited them; a changed study is
// refused.
#include "rig/study/study_start.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "model/space/simulated_observer.hpp"
#include "model/study/study_results.hpp"
#include "rig/study/actuator_presenter.hpp"
#include "tests/model/study/study_test_support.hpp"
#include "tests/playback/jack_stream_settings.hpp"
#include "tests/rig/bundled_sound.hpp"
#include "tests/support/jack_server.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::rig {
namespace {

namespace study = model::study;
using Field = StudyStartRefused::Field;

// Three catalog pairings the bundled catalog has: no meshing beyond the stylus's cached modes.
study::StudyDefinition catalog_study(study::StudyMode mode = study::StudyMode::actuator) {
  study::StudyDefinition d;
  d.stimuli = {{"cryon/office", "cryon", "office"},
               {"stab/office", "stab", "office"},
               {"vero2/office", "vero2", "office"}};
  d.mode = mode;
  d.plan = study::PlanKind::file;
  d.practice = 0;
  d.listed_trials = {{0, 1, 2, 1}, {1, 2, 0, 1}};
  return d;
}

StudyStartRequest request_for(const std::filesystem::path& folder, const std::string& participant,
                              std::optional<study::StudyDefinition> definition) {
  StudyStartRequest r;
  r.settings.study = folder;
  r.settings.participant = participant;
  r.definition = std::move(definition);
  return r;
}

std::string file_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The refusal a request gets, or a failure when it is not refused.
std::optional<StudyStartRefused> refusal_of(StudyStartRequest request) {
  try {
    StudyStart start(std::move(request));
  } catch (const StudyStartRefused& e) {
    return e;
  }
  return std::nullopt;
}

// Answers each trial after feeling the reference, A and B once.
class FeelingParticipant final : public study::Respondent {
 public:
  bool agree(const study::StudyTexts& texts) override {
    seen = texts;
    return true;
  }
  study::Answer answer(const study::TrialPrompt&, const std::function<void(study::Role)>& play) override {
    for (char c : std::string("RAB")) play(static_cast<study::Role>(c));
    return {model::space::Choice::left, 2.0};
  }
  void rest(std::size_t, std::size_t) override {}
  study::StudyTexts seen;
};

TEST(StudyStart, EachRefusalNamesItsFieldAndWritesNothing) {
  const auto dir = nibrig::test::scratch_dir("study_start_refusals");
  const auto fresh = dir / "fresh";
  struct Case {
    std::string what;
    StudyStartRequest request;
    Field field;
    std::string says;
  };
  std::vector<Case> cases;
  cases.push_back({"malformed ID", request_for(fresh, "P 01", catalog_study()), Field::participant, "P 01"});
  cases.push_back({"no list", request_for(fresh, "P01", std::nullopt), Field::definition,
                   "a new study needs its stimulus list"});
  study::StudyDefinition two = catalog_study();
  two.stimuli.pop_back();
  two.listed_trials.clear();
  cases.push_back({"two stimuli", request_for(fresh, "P01", two), Field::definition, "stimuli"});
  StudyStartRequest resume = request_for(fresh, "P01", std::nullopt);
  resume.settings.resume = true;
  cases.push_back({"nothing to resume", resume, Field::folder, "to resume"});
  StudyStartRequest resume_new = request_for(fresh, "P01", catalog_study());
  resume_new.settings.resume = true;
  cases.push_back({"resume in a new study", resume_new, Field::participant, "no session"});
  study::StudyDefinition unknown = catalog_study();
  unknown.stimuli[1] = {"quill/office", "quill", "office"};
  cases.push_back({"unknown tool", request_for(fresh, "P01", unknown), Field::stimulus, "stimulus 'quill/office'"});
  study::StudyDefinition bad_point = catalog_study();
  bad_point.stimuli[2] = {"D1", "DM85:half,vero:0.5,tip=2mm", "office"};
  cases.push_back({"malformed design point", request_for(fresh, "P01", bad_point), Field::stimulus,
                   "stimulus 'D1'"});
  cases.push_back({"rig mode without a rig", request_for(fresh, "P01", catalog_study(study::StudyMode::rig)),
                   Field::rig, "rig mode needs a rig"});
  StudyStartRequest replay = request_for(fresh, "P01", catalog_study(study::StudyMode::rig));
  replay.mount = [](const std::string&) {};
  replay.rig = []() -> RigRequest { throw std::invalid_argument("the replay rig cannot present a stimulus"); };
  cases.push_back({"a rig that cannot present", replay, Field::rig, "replay rig"});
  for (auto& c : cases) {
    const auto refused = refusal_of(std::move(c.request));
    ASSERT_TRUE(refused) << c.what << ": not refused";
    EXPECT_EQ(refused->field(), c.field) << c.what << ": " << field_name(refused->field());
    EXPECT_NE(std::string(refused->what()).find(c.says), std::string::npos) << c.what << ": " << refused->what();
    EXPECT_FALSE(std::filesystem::exists(fresh)) << c.what << ": a refused start writes nothing";
  }
}

TEST(StudyStart, WithNothingPresentedTheSessionIsReadyAndASecondParticipantJoinsTheEditedFolder) {
  const auto dir = nibrig::test::scratch_dir("study_start_nothing");
  const auto folder = dir / "study";
  const study::StudyDefinition d = catalog_study();
  ReadyStudy first = start_study(request_for(folder, "P01", d));
  ASSERT_TRUE(first.session);
  EXPECT_NE(dynamic_cast<study::NothingPresented*>(first.presenter.get()), nullptr)
      << "no audition given: nothing is presented";
  EXPECT_EQ(first.session->definition().listed_trials.size(), 2u);
  // The bundled texts were copied in; the experimenter edits them there.
  EXPECT_EQ(file_text(folder / study::kConsentFile), file_text(nibrig::test::assets_dir() / "experiment/consent.txt"));
  FeelingParticipant p1;
  ASSERT_TRUE(study::run_study(*first.session, p1).complete);
  std::ofstream(folder / study::kInstructionsFile) << "Edited: which is closer?\n";

  // A second participant with the same list joins: the folder's texts, not the bundled ones.
  ReadyStudy second = start_study(request_for(folder, "P02", d));
  FeelingParticipant p2;
  ASSERT_TRUE(study::run_study(*second.session, p2).complete);
  EXPECT_EQ(p2.seen.instructions, "Edited: which is closer?\n");
  // And one resuming without a list gets the folder's own study: P02 finished, so nothing is asked.
  StudyStartRequest resume = request_for(folder, "P02", std::nullopt);
  resume.settings.resume = true;
  StudyStart again(std::move(resume));
  EXPECT_EQ(again.definition().stimuli.size(), d.stimuli.size());
  const auto results = study::read_study(folder);
  ASSERT_EQ(results.participants.size(), 2u);
  for (const auto& participant : results.participants) {
    ASSERT_EQ(participant.responses.size(), 2u) << participant.record.id;
    EXPECT_EQ(participant.responses[0].plays, "RAB");
  }

  // The same ID again, without resume: taken, and its answers stay as they were.
  const auto before = std::filesystem::file_size(study::participant_folder(folder, "P01") / study::kResponsesFile);
  const auto taken = refusal_of(request_for(folder, "P01", d));
  ASSERT_TRUE(taken);
  EXPECT_EQ(taken->field(), Field::participant);
  EXPECT_NE(std::string(taken->what()).find("already has answers"), std::string::npos) << taken->what();
  EXPECT_EQ(std::filesystem::file_size(study::participant_folder(folder, "P01") / study::kResponsesFile), before);
}

TEST(StudyStart, AChangedStudyIsRefusedAndTheFoldersStudyKept) {
  const auto dir = nibrig::test::scratch_dir("study_start_changed");
  const auto folder = dir / "study";
  start_study(request_for(folder, "P01", catalog_study()));
  const std::string kept = file_text(folder / study::kStudyFile);
  study::StudyDefinition other = catalog_study();
  other.stimuli[2] = {"cryon/note", "cryon", "note"};
  const auto refused = refusal_of(request_for(folder, "P02", other));
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->field(), Field::folder);
  EXPECT_NE(std::string(refused->what()).find("holds another study: stimulus 3"), std::string::npos)
      << refused->what();
  study::StudyDefinition more_practice = catalog_study();
  more_practice.practice = 2;
  const auto practice = refusal_of(request_for(folder, "P02", more_practice));
  ASSERT_TRUE(practice);
  EXPECT_EQ(practice->field(), Field::folder);
  EXPECT_EQ(file_text(folder / study::kStudyFile), kept);
  EXPECT_FALSE(std::filesystem::exists(study::participant_folder(folder, "P02")));
}

TEST(StudyStart, InRigModeTheOperatorIsToldAndEachStimulusIsSweptOnTheRigAskedFor) {
  const auto dir = nibrig::test::scratch_dir("study_start_rig");
  StudyStartRequest request = request_for(dir / "study", "R01", catalog_study(study::StudyMode::rig));
  std::size_t asked_for_rig = 0;
  request.rig = [&] {
    ++asked_for_rig;
    RigRequest r;
    r.kind = RigKind::simulated;
    r.speedup = 0;  // as fast as it computes
    return r;
  };
  std::vector<std::string> mounts, notices;
  request.mount = [&](const std::string& m) { mounts.push_back(m); };
  request.notice = [&](const std::string& m) { notices.push_back(m); };
  bool audition_asked = false;
  std::optional<playback::LiveAudition> unused;
  request.audition = [&]() -> playback::LiveAudition& {
    audition_asked = true;
    return unused.emplace(rt::EngineSettings{});
  };
  std::size_t sounds_made = 0;
  ReadyStudy ready = start_study(std::move(request), [&](std::size_t, std::size_t) { ++sounds_made; });
  EXPECT_EQ(asked_for_rig, 1u);
  EXPECT_EQ(sounds_made, 0u) << "rig mode makes no sound for the actuator";
  EXPECT_FALSE(audition_asked) << "rig mode does not touch the actuator";
  const auto* turntable = dynamic_cast<TurntablePresenter*>(ready.presenter.get());
  ASSERT_NE(turntable, nullptr);
  FeelingParticipant participant;
  ASSERT_TRUE(study::run_study(*ready.session, participant).complete);
  EXPECT_EQ(turntable->runs(), 6u) << "three stimuli felt in each of two trials";
  ASSERT_FALSE(notices.empty());
  EXPECT_EQ(notices[0], "trial with reference cryon/office, A stab/office, B vero2/office: have them at hand");
  ASSERT_FALSE(mounts.empty());
  EXPECT_EQ(mounts[0], "mount cryon on office (the reference)");
}

TEST(StudyStartJack, InActuatorModeTheSoundsAreMadeAndEachTrialLoadsItsThreeIntoTheAudition) {
  nibrig::testing::JackServer server;
  const auto dir = nibrig::test::scratch_dir("study_start_actuator_jack");
  StudyStartRequest request = request_for(dir / "study", "P01", catalog_study());
  playback::LiveAudition audition(rt::EngineSettings{});
  audition.open(playback::testing::jack_settings("study_start"));
  std::size_t lent = 0;
  request.audition = [&]() -> playback::LiveAudition& {
    ++lent;
    return audition;
  };
  std::vector<std::pair<std::size_t, std::size_t>> progress;
  StudyStart start(std::move(request));
  EXPECT_EQ(lent, 0u) << "the audition is asked for only when the session is made ready";
  start.prepare([&](std::size_t done, std::size_t total) { progress.emplace_back(done, total); });
  const std::vector<std::pair<std::size_t, std::size_t>> expected = {{1, 3}, {2, 3}, {3, 3}};
  EXPECT_EQ(progress, expected);
  ReadyStudy ready = start.ready();
  EXPECT_EQ(lent, 1u);
  ASSERT_NE(dynamic_cast<ActuatorPresenter*>(ready.presenter.get()), nullptr);
  ready.session->begin();
  // The first listed trial is reference 0, A 1, B 2: the audition's slots hold those sounds, named
  // as the bundled catalog and stylus make them.
  const auto& names = audition.names();
  ASSERT_GE(names.size(), 3u);
  EXPECT_EQ(names[0], testing::bundled_sound("cryon", "office").name);
  EXPECT_EQ(names[1], testing::bundled_sound("stab", "office").name);
  EXPECT_EQ(names[2], testing::bundled_sound("vero2", "office").name);
  ready.session->play(study::Role::left);
  ready.session->play(study::Role::reference);
  ready.session->play(study::Role::right);
  ready.session->answer(model::space::Choice::right);
  // The second trial (reference 1, A 2, B 0) is loaded as the first is answered.
  EXPECT_EQ(names[0], testing::bundled_sound("stab", "office").name);
  EXPECT_EQ(names[2], testing::bundled_sound("cryon", "office").name);
  ready.session->pause();
  EXPECT_EQ(study::read_study(dir / "study").participants.at(0).responses.at(0).plays, "ARB");
}

}  // namespace
}  // namespace nibrig::rig
