#include "model/study/response_log.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "model/io/format_error.hpp"
#include "tests/model/study/study_test_support.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::study {
namespace {

const std::vector<std::string> kLogStimuli{"crayon/office", "D1", "pencil/stone"};
constexpr int kLogLastStage = 2;  // a two-stage study's

LoggedResponse response(std::size_t trial, space::Choice chosen) {
  LoggedResponse r;
  r.trial = trial;
  r.practice = trial == 1;
  r.planned = {trial % 3, (trial + 1) % 3, (trial + 2) % 3, 1};
  r.chosen = chosen;
  r.response_s = 1.25 * static_cast<double>(trial);
  r.plays = "RARB";
  r.answered_utc = "2026-11-26T04:00:00Z";
  return r;
}

std::string contents(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(ResponseLog, WhatIsAppendedReadsBackTheSame) {
  const auto file = nibrig::test::scratch_dir("response_log_round_trip") / "responses.csv";
  {
    ResponseLog log(file, kLogStimuli);
    log.append(response(1, space::Choice::left));
    log.append(response(2, space::Choice::right));
  }
  {
    ResponseLog log(file, kLogStimuli);  // reopened: appends after what is there, no 2nd header
    log.append(response(3, space::Choice::left));
  }
  const ResponseFile read = read_response_file(file, kLogStimuli, kLogLastStage);
  EXPECT_TRUE(read.warnings.empty());
  ASSERT_EQ(read.responses.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const LoggedResponse want = response(i + 1, i == 1 ? space::Choice::right : space::Choice::left);
    const LoggedResponse& got = read.responses[i];
    EXPECT_EQ(got.trial, want.trial);
    EXPECT_EQ(got.practice, want.practice);
    EXPECT_EQ(got.planned.reference, want.planned.reference);
    EXPECT_EQ(got.planned.left, want.planned.left);
    EXPECT_EQ(got.planned.right, want.planned.right);
    EXPECT_EQ(got.chosen, want.chosen);
    EXPECT_NEAR(got.response_s, want.response_s, 5e-4);  // written to the millisecond
    EXPECT_EQ(got.plays, "RARB");
  }
}

TEST(ResponseLog, ALineCutOffByACrashIsDroppedWithAWarningAndRemovedBeforeTheNextAppend) {
  const auto file = nibrig::test::scratch_dir("response_log_cut_off") / "responses.csv";
  {
    ResponseLog log(file, kLogStimuli);
    log.append(response(1, space::Choice::left));
    log.append(response(2, space::Choice::right));
  }
  // A process killed in the middle of writing trial 3.
  std::ofstream(file, std::ios::app) << "3,0,1,crayon/office,D1,pen";
  const ResponseFile read = read_response_file(file, kLogStimuli, kLogLastStage);
  ASSERT_EQ(read.responses.size(), 2u);
  ASSERT_EQ(read.warnings.size(), 1u);
  EXPECT_NE(read.warnings[0].find("line 4 is cut off"), std::string::npos) << read.warnings[0];
  {
    ResponseLog log(file, kLogStimuli);
    EXPECT_TRUE(log.removed_cut_off_line());
    log.append(response(3, space::Choice::left));
  }
  const ResponseFile after = read_response_file(file, kLogStimuli, kLogLastStage);
  EXPECT_TRUE(after.warnings.empty());
  ASSERT_EQ(after.responses.size(), 3u);
  const std::string text = contents(file);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 4) << "header and three whole lines:\n" << text;
}

TEST(ResponseLog, BadLinesAreRefusedNamingTheFileLineAndField) {
  const auto dir = nibrig::test::scratch_dir("response_log_bad");
  const std::string header =
      "trial,practice,stage,reference,left,right,chosen,response_s,plays,answered_utc\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"1,0,1,crayon/office,D1,chalk/stone,left,1.0,RAB,t\n", "line 2, field 'right'"},
      {"2,0,1,crayon/office,D1,pencil/stone,left,1.0,RAB,t\n", "expected trial 1"},
      {"1,0,1,crayon/office,D1,pencil/stone,up,1.0,RAB,t\n", "field 'chosen'"},
      {"1,0,1,crayon/office,D1,pencil/stone,left,-1,RAB,t\n", "field 'response_s'"},
      {"1,0,1,crayon/office,D1,pencil/stone,left,1e308,RAB,t\n", "field 'response_s'"},
      {"1,0,1,crayon/office,D1,pencil/stone,left,1.0,RXB,t\n", "field 'plays'"},
      {"1,2,1,crayon/office,D1,pencil/stone,left,1.0,RAB,t\n", "field 'practice'"},
      {"1,0,7,crayon/office,D1,pencil/stone,left,1.0,RAB,2026-11-26T04:00:00Z\n",
       "field 'stage'"},
      {"1,0,0,crayon/office,D1,pencil/stone,left,1.0,RAB,2026-11-26T04:00:00Z\n",
       "field 'stage'"},
      {"1,0,1,crayon/office,D1,pencil/stone,left,1.0,RAB,yesterday\n", "field 'answered_utc'"},
      {"1,0,1,crayon/office,D1,pencil/stone,left,1.0,RAB,2026-02-29T04:00:00Z\n",
       "field 'answered_utc'"},
      {"1,0,1,crayon/office,D1,pencil/stone,left,1.0,RAB,2026-11-26T24:00:00Z\n",
       "field 'answered_utc'"},
      {"1,0,1,crayon/office,D1,pencil/stone,left,1.0,RAB,2026-11-26T04:00:00Z,extra\n",
       "expected 10 fields"},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto file = dir / ("bad" + std::to_string(i) + ".csv");
    std::ofstream(file) << header << cases[i].first;
    try {
      read_response_file(file, kLogStimuli, kLogLastStage);
      ADD_FAILURE() << "accepted " << cases[i].first;
    } catch (const io::FormatError& e) {
      EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(cases[i].second), std::string::npos) << e.what();
    }
  }
}

TEST(ParticipantFile, KeepsAFull64BitSeedAndRefusesABadId) {
  const auto file = nibrig::test::scratch_dir("participant_file") / "participant.json";
  const ParticipantRecord record{"P01", 18446744073709551557ull, "a person", "2026-11-26T04:00:00Z"};
  write_participant_file(file, record);
  const ParticipantRecord back = read_participant_file(file);
  EXPECT_EQ(back.seed, record.seed);  // a double would round it
  EXPECT_EQ(back.id, "P01");
  EXPECT_NO_THROW(check_participant_id("P-01_b.2"));
  for (const std::string& bad : std::vector<std::string>{"", "../P01", ".hidden", "P 01", std::string(65, 'x')})
    EXPECT_THROW(check_participant_id(bad), std::invalid_argument) << bad;
  EXPECT_NE(seed_of_participant("P01"), seed_of_participant("P02"));
}

}  // namespace
}  // namespace nibrig::model::study
