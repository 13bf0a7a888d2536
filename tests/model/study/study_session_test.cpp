#include "model/study/study_session.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <random>

#include "model/io/triplets.hpp"
#include "model/space/simulated_observer.hpp"
#include "model/study/study_results.hpp"
#include "tests/model/study/study_test_support.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::study {
namespace {

Eigen::MatrixXd session_truth(std::size_t stimuli) {
  std::mt19937_64 generator(21);
  return space::random_space(2, stimuli, generator);
}

StudySettings settings_for(const std::filesystem::path& study, const std::string& id) {
  StudySettings s;
  s.study = study;
  s.participant = id;
  s.seed = 5;
  s.respondent = "simulated";
  return s;
}

std::string file_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The judgments file of one participant, as `experiment report` writes it.
std::string judgments_text(const std::filesystem::path& study, const std::string& id,
                           const std::filesystem::path& out) {
  io::write_triplet_csv(out, study_judgments(read_study(study), JudgmentSelection::every_answer, id));
  return file_text(out);
}

// A study small enough to run many times: 7 stimuli, the paper's plan (stage 1: 53 × 2 trials).
StudyDefinition small_study() {
  StudyDefinition d = test::definition_of(7);
  d.break_every = 25;
  return d;
}

TEST(StudySession, AnUninterruptedRunAnswersEveryTrialOnDiskWithPlaysAndRests) {
  const auto study = test::make_study(nibrig::test::scratch_dir("session_full"), small_study());
  test::StoppingParticipant p(session_truth(7), 99);
  NothingPresented nothing;
  const StudyResult r = run_study(settings_for(study, "P01"), nothing, p);
  EXPECT_TRUE(r.complete);
  EXPECT_EQ(p.seen_texts.instructions, "Which is closer to the reference?\n");
  EXPECT_EQ(p.seen_texts.consent, "I agree.\n");
  const StudyData data = read_study(study);
  ASSERT_EQ(data.participants.size(), 1u);
  const auto& responses = data.participants[0].responses;
  EXPECT_EQ(responses.size(), r.answered);
  EXPECT_EQ(data.participants[0].record.seed, 5u);
  std::size_t main = 0;
  for (const auto& x : responses) {
    EXPECT_EQ(x.plays.substr(0, 4), "RARB");  // the simulated participant's exploration
    EXPECT_GT(x.response_s, 1.0);             // its non-decision time alone is 1 s
    main += x.practice ? 0 : 1;
  }
  EXPECT_EQ(responses.front().practice, true);
  // A rest after every 25 main trials, except after the last.
  ASSERT_FALSE(p.rests.empty());
  EXPECT_EQ(p.rests.size(), (main - 1) / 25);
  EXPECT_EQ(p.rests.front(), 3u + 25u);  // counted with the 3 practice trials
}

TEST(StudySession, StoppedAndResumedGivesTheSameJudgmentsAsOneSession) {
  const auto dir = nibrig::test::scratch_dir("session_resume");
  const auto whole = test::make_study(dir / "whole", small_study());
  const auto parts = test::make_study(dir / "parts", small_study());
  NothingPresented nothing;
  test::StoppingParticipant one(session_truth(7), 99);
  run_study(settings_for(whole, "P01"), nothing, one);

  test::StoppingParticipant first(session_truth(7), 99, 40);
  const StudyResult stopped = run_study(settings_for(parts, "P01"), nothing, first);
  EXPECT_FALSE(stopped.complete);
  EXPECT_EQ(stopped.answered, 39u);  // trial 40 was in progress: not kept
  StudySettings again = settings_for(parts, "P01");
  again.resume = true;
  test::StoppingParticipant second(session_truth(7), 99);
  const StudyResult resumed = run_study(again, nothing, second);
  EXPECT_TRUE(resumed.complete);
  EXPECT_EQ(resumed.resumed_at, 39u);
  EXPECT_EQ(second.prompts.front(), 40u);
  EXPECT_EQ(judgments_text(whole, "P01", dir / "whole.csv"),
            judgments_text(parts, "P01", dir / "parts.csv"));
}

TEST(StudySession, KilledWithSigkillAtARandomTrialAndResumedGivesTheSameJudgmentsFile) {
  const auto dir = nibrig::test::scratch_dir("session_kill");
  const auto whole = test::make_study(dir / "whole", small_study());
  const auto killed = test::make_study(dir / "killed", small_study());
  NothingPresented nothing;
  test::StoppingParticipant one(session_truth(7), 99);
  const StudyResult full = run_study(settings_for(whole, "P01"), nothing, one);
  std::random_device entropy;
  const std::size_t kill_at = 2 + entropy() % (full.answered - 2);
  SCOPED_TRACE("killed while trial " + std::to_string(kill_at) + " was being answered");

  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // The child answers until trial kill_at and is killed there: no destructor, no flush runs.
    class Dying final : public Respondent {
     public:
      Dying(std::size_t at) : inner_(session_truth(7), 99), at_(at) {}
      bool agree(const StudyTexts& t) override { return inner_.agree(t); }
      Answer answer(const TrialPrompt& prompt, const std::function<void(Role)>& play) override {
        if (prompt.number == at_) kill(getpid(), SIGKILL);
        return inner_.answer(prompt, play);
      }
      void rest(std::size_t, std::size_t) override {}

     private:
      test::StoppingParticipant inner_;
      std::size_t at_;
    } dying(kill_at);
    run_study(settings_for(killed, "P01"), nothing, dying);
    _exit(0);  // not reached
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
  const StudyData partial = read_study(killed);
  ASSERT_EQ(partial.participants.size(), 1u);
  EXPECT_EQ(partial.participants[0].responses.size(), kill_at - 1) << "every answer before the kill";

  StudySettings again = settings_for(killed, "P01");
  again.resume = true;
  again.seed.reset();  // the participant's file has it
  test::StoppingParticipant rest(session_truth(7), 99);
  EXPECT_TRUE(run_study(again, nothing, rest).complete);
  EXPECT_EQ(judgments_text(whole, "P01", dir / "whole.csv"),
            judgments_text(killed, "P01", dir / "killed.csv"));
}

TEST(StudySession, ATakenIdAsksForResumeOrANewIdBeforeAnythingStarts) {
  const auto study = test::make_study(nibrig::test::scratch_dir("session_taken"), small_study());
  NothingPresented nothing;
  test::StoppingParticipant p(session_truth(7), 1, 5);
  run_study(settings_for(study, "P01"), nothing, p);
  test::StoppingParticipant q(session_truth(7), 1);
  try {
    run_study(settings_for(study, "P01"), nothing, q);
    ADD_FAILURE() << "a taken ID was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--resume"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("new participant ID"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(q.prompts.empty()) << "refused before the first trial";
  StudySettings other_seed = settings_for(study, "P01");
  other_seed.resume = true;
  other_seed.seed = 6;
  EXPECT_THROW(run_study(other_seed, nothing, q), std::invalid_argument);
  StudySettings nobody = settings_for(study, "P02");
  nobody.resume = true;
  EXPECT_THROW(run_study(nobody, nothing, q), std::invalid_argument);
  EXPECT_TRUE(q.prompts.empty());
}

// Two sessions of one participant at once would both append the next trials (duplicates in the
// log): the second is refused, naming the one that runs, and runs once that one ended.
TEST(StudySession, ASecondSessionOfAParticipantIsRefusedNamingTheFirst) {
  const auto study = test::make_study(nibrig::test::scratch_dir("session_locked"), small_study());
  NothingPresented nothing;
  for (const bool resume : {false, true}) {
    SCOPED_TRACE(resume ? "resumed" : "new");
    StudySettings s = settings_for(study, "P01");
    s.resume = resume;
    StudySession first(s, nothing);
    try {
      StudySession second(s, nothing);
      ADD_FAILURE() << "two sessions of P01 at once";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("pid " + std::to_string(::getpid())), std::string::npos)
          << e.what();
    }
    first.begin();  // the new participant's record is written: the next round resumes it
  }
  StudySettings s = settings_for(study, "P01");
  s.resume = true;
  EXPECT_NO_THROW((StudySession{s, nothing}));  // once the other session ended
}

// Every participant folder on disk is counted or named in a warning saying why not: a report must
// not drop answers without a word, merge two people under one ID, or fail on a participant killed
// before the first answer.
TEST(StudySession, TheReportCountsEveryParticipantOrSaysWhyNot) {
  const auto study = test::make_study(nibrig::test::scratch_dir("session_counted"), small_study());
  NothingPresented nothing;
  for (const char* id : {"P01", "P02", "P03"}) {
    test::StoppingParticipant p(session_truth(7), 1, 30);
    run_study(settings_for(study, id), nothing, p);
  }
  test::StoppingParticipant killed(session_truth(7), 1, 1);
  run_study(settings_for(study, "P04"), nothing, killed);
  std::filesystem::remove(participant_folder(study, "P02") / kParticipantFile);
  ParticipantRecord renamed = read_participant_file(participant_folder(study, "P03") / kParticipantFile);
  renamed.id = "P01";
  write_participant_file(participant_folder(study, "P03") / kParticipantFile, renamed);

  const StudyData data = read_study(study);
  ASSERT_EQ(data.participants.size(), 2u);
  EXPECT_EQ(data.participants[0].record.id, "P01");
  EXPECT_TRUE(has_main_answers(data.participants[0]));
  // Killed before the first answer: read, but left out of the report's statistics, which failed
  // on it ("agreement test: 0 of 0").
  EXPECT_EQ(data.participants[1].record.id, "P04");
  EXPECT_FALSE(has_main_answers(data.participants[1]));
  struct Expected {
    const char* folder;
    const char* why;
  };
  for (const Expected& e : {Expected{"P02", "answers"}, Expected{"P03", "names participant 'P01'"}}) {
    const auto named = std::find_if(data.warnings.begin(), data.warnings.end(), [&](const auto& w) {
      return w.find(participant_folder(study, e.folder).string()) != std::string::npos;
    });
    ASSERT_NE(named, data.warnings.end()) << e.folder << " is neither counted nor named";
    EXPECT_NE(named->find(e.why), std::string::npos) << *named;
  }
}

// The trial's report took an answer appended beyond the plan: no session of the study writes one.
TEST(StudySession, AnAnswerBeyondThePlanIsRefusedNamingItsLine) {
  const auto study = test::make_study(nibrig::test::scratch_dir("session_beyond"), small_study());
  NothingPresented nothing;
  test::StoppingParticipant p(session_truth(7), 1);
  run_study(settings_for(study, "P01"), nothing, p);
  const auto log = participant_folder(study, "P01") / kResponsesFile;
  std::vector<std::string> lines;
  {
    std::ifstream in(log);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
  }
  ASSERT_GE(lines.size(), 3u);
  EXPECT_NO_THROW(read_study(study));
  const std::size_t answered = lines.size() - 1;
  const std::string last = lines.back();
  std::ofstream(log, std::ios::app) << std::to_string(answered + 1) << last.substr(last.find(',')) << "\n";
  try {
    read_study(study);
    ADD_FAILURE() << "an answer beyond the plan was read";
  } catch (const io::FormatError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(log.string()), std::string::npos) << message;
    EXPECT_NE(message.find("line " + std::to_string(answered + 2)), std::string::npos) << message;
    EXPECT_NE(message.find("beyond the study's plan"), std::string::npos) << message;
  }
}

TEST(StudySession, DecliningTheConsentRecordsNothing) {
  const auto study = test::make_study(nibrig::test::scratch_dir("session_declined"), small_study());
  NothingPresented nothing;
  test::StoppingParticipant p(session_truth(7), 1);
  p.agrees = false;
  EXPECT_TRUE(run_study(settings_for(study, "P01"), nothing, p).declined);
  EXPECT_TRUE(p.prompts.empty());
  EXPECT_FALSE(std::filesystem::exists(participant_folder(study, "P01")));
}

TEST(StudySession, AnotherStudyInTheSameFolderIsRefusedNamingTheDifference) {
  const auto dir = nibrig::test::scratch_dir("session_other_study");
  const auto study = test::make_study(dir, small_study());
  StudyDefinition other = small_study();
  other.stimuli[2].surface = "stone";
  try {
    create_or_join_study(study, other, dir.parent_path() / "instructions-src.txt",
                         dir.parent_path() / "consent-src.txt");
    ADD_FAILURE() << "another study was joined";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("stimulus 3"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(create_or_join_study(study, small_study(), dir.parent_path() / "instructions-src.txt",
                                       dir.parent_path() / "consent-src.txt"));
}

}  // namespace
}  // namespace nibrig::model::study
