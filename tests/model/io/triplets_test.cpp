#include "model/io/triplets.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "tests/model/io/io_test_files.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::model::io {
namespace {

using nibrig::test::expect_message_names;
using nibrig::test::format_error_of;

std::filesystem::path lagunas_file() {
  return nibrig::test::shared_data() / "lagunas2019" / "answers_processed_train.json";
}
std::filesystem::path salmon_file() {
  return nibrig::test::shared_data() / "salmon_alien_eggs" / "responses_train.csv";
}

TEST(Triplets, LagunasRealData) {
  const TripletSet set = read_lagunas_json(lagunas_file());
  // Counts from PROVENANCE.md: 22,801 queries, 92,892 responses, 100 materials.
  EXPECT_EQ(set.triplets.size(), 22'801u);
  EXPECT_EQ(response_count(set), 92'892u);
  ASSERT_EQ(set.stimuli.size(), 100u);
  // material_names_sorted.txt: line 1 "alum-bronze" is id 0, line 100 "yellow-plastic" is id 99.
  EXPECT_EQ(set.stimuli.front(), "alum-bronze");
  EXPECT_EQ(set.stimuli.back(), "yellow-plastic");
  // The first query in the file is answers[0] = [84, 7, 81] with agreement [3, 1].
  EXPECT_EQ(set.triplets[0].reference, 84u);
  EXPECT_EQ(set.triplets[0].a, 7u);
  EXPECT_EQ(set.triplets[0].b, 81u);
  EXPECT_EQ(set.triplets[0].count_a, 3);
  EXPECT_EQ(set.triplets[0].count_b, 1);
  // The caution of PROVENANCE.md holds: the first candidate is never the minority choice.
  EXPECT_TRUE(std::all_of(set.triplets.begin(), set.triplets.end(),
                          [](const Triplet& t) { return t.count_a >= t.count_b; }));
}

TEST(Triplets, SalmonRealData) {
  const TripletSet set = read_salmon_csv(salmon_file());
  EXPECT_EQ(set.triplets.size(), 15'054u);
  EXPECT_EQ(response_count(set), 15'054u);
  ASSERT_EQ(set.stimuli.size(), 300u);
  EXPECT_EQ(set.stimuli.front(), "i0002");
  EXPECT_EQ(set.stimuli.back(), "i0600");
  // Row 1: participant 1099, Center i0464, Left i0532, Right i0546, Answer i0532.
  const Triplet& first = set.triplets.front();
  EXPECT_EQ(set.stimuli[first.reference], "i0464");
  EXPECT_EQ(set.stimuli[first.a], "i0532");
  EXPECT_EQ(set.stimuli[first.b], "i0546");
  EXPECT_EQ(first.count_a, 1);
  EXPECT_EQ(first.count_b, 0);
  EXPECT_EQ(first.observer, "1099");
  std::set<std::string> observers;
  for (const Triplet& t : set.triplets) observers.insert(t.observer);
  EXPECT_EQ(observers.size(), 231u);  // distinct Participant.ID values in the file
}

TEST(Triplets, DispatchByContent) {
  EXPECT_EQ(read_triplets(lagunas_file()).stimuli.size(), 100u);
  EXPECT_EQ(read_triplets(salmon_file()).stimuli.size(), 300u);
  const auto dir = nibrig::test::scratch_dir("triplets_dispatch");
  nibrig::test::write_gzip(dir / "ours.csv.gz", "reference,a,b,count_a,count_b\nx,y,z,2,1\n");
  EXPECT_EQ(read_triplets(dir / "ours.csv.gz").stimuli, (std::vector<std::string>{"x", "y", "z"}));
  nibrig::test::write_text(dir / "lagunas.txt", "{\"answers\": [[0, 1, 2]], \"agreement\": [[1, 0]]}");
  EXPECT_EQ(read_triplets(dir / "lagunas.txt").stimuli, (std::vector<std::string>{"0", "1", "2"}));
  nibrig::test::write_text(dir / "other.csv", "who,what\n1,2\n");
  expect_message_names(
      format_error_of([&] { read_triplets(dir / "other.csv"); }),
      {"other.csv", "line 1", "unrecognised triplet file", "reference,a,b,count_a,count_b"});
}

TEST(Triplets, QueriesNeedNoResponsesJudgmentsDo) {
  const auto dir = nibrig::test::scratch_dir("triplet_queries");
  nibrig::test::write_text(dir / "q.csv", "reference,a,b,count_a,count_b\nx,y,z,0,0\ny,z,x,2,1\n");
  const TripletSet queries = read_triplet_queries(dir / "q.csv");
  ASSERT_EQ(queries.triplets.size(), 2u);
  EXPECT_EQ(queries.stimuli[queries.triplets[0].reference], "x");
  expect_message_names(format_error_of([&] { read_triplets(dir / "q.csv"); }),
                       {"q.csv", "line 2", "at least one response"});
  nibrig::test::write_text(dir / "q.json", R"({"answers": [[0, 1, 2]], "agreement": [[0, 0]]})");
  EXPECT_EQ(read_triplet_queries(dir / "q.json").triplets.size(), 1u);
  // `space predict --help` promises counts are ignored: a query file may leave them out, while a
  // judgment file without them is still refused.
  nibrig::test::write_text(dir / "bare.csv", "reference,a,b\nx,y,z\ny,z,x\n");
  const TripletSet bare = read_triplet_queries(dir / "bare.csv");
  ASSERT_EQ(bare.triplets.size(), 2u);
  EXPECT_EQ(bare.stimuli[bare.triplets[1].a], "z");
  EXPECT_EQ(bare.triplets[1].count_a + bare.triplets[1].count_b, 0) << "no answers were given";
  expect_message_names(format_error_of([&] { read_triplets(dir / "bare.csv"); }),
                       {"bare.csv", "missing column 'count_a'"});
  // Everything but the counts is still checked.
  nibrig::test::write_text(dir / "self.csv", "reference,a,b,count_a,count_b\nx,x,z,0,0\n");
  expect_message_names(format_error_of([&] { read_triplet_queries(dir / "self.csv"); }),
                       {"self.csv", "line 2", "three different stimuli"});
}

TEST(Triplets, CsvRoundTrip) {
  const auto dir = nibrig::test::scratch_dir("triplets_round_trip");
  TripletSet set;
  set.stimuli = {"8B pencil", "vero1", "DM851"};  // order of first appearance below
  set.triplets = {{0, 1, 2, 3, 1, "ann"}, {1, 2, 0, 0, 2, ""}, {2, 0, 1, 5, 5, "bob"}};
  write_triplet_csv(dir / "t.csv", set);
  const TripletSet back = read_triplet_csv(dir / "t.csv");
  EXPECT_EQ(back.stimuli, set.stimuli);
  ASSERT_EQ(back.triplets.size(), set.triplets.size());
  for (std::size_t i = 0; i < set.triplets.size(); ++i) {
    EXPECT_EQ(back.triplets[i].reference, set.triplets[i].reference);
    EXPECT_EQ(back.triplets[i].a, set.triplets[i].a);
    EXPECT_EQ(back.triplets[i].b, set.triplets[i].b);
    EXPECT_EQ(back.triplets[i].count_a, set.triplets[i].count_a);
    EXPECT_EQ(back.triplets[i].count_b, set.triplets[i].count_b);
    EXPECT_EQ(back.triplets[i].observer, set.triplets[i].observer);
  }
}

// A spreadsheet quotes text fields ("cryon/office"); read as text, the quotes made a 16th stimulus
// of a 15-tool study. RFC 4180: a quoted field's quotes are not part of it, '""' is one quote.
TEST(Triplets, QuotedFieldsAreTheSameStimuliAsUnquoted) {
  const auto dir = nibrig::test::scratch_dir("triplets_quoted");
  nibrig::test::write_text(dir / "t.csv",
                           "\"reference\",\"a\",\"b\",\"count_a\",\"count_b\"\r\n"
                           "cryon/office,stab/office,vero/office,3,1\r\n"
                           "\"cryon/office\",\"vero/office\",\"stab/office\",\"2\",0\r\n"
                           "\"pencil \"\"8B\"\"\",cryon/office,vero/office,1,1\r\n");
  const TripletSet set = read_triplets(dir / "t.csv");
  EXPECT_EQ(set.stimuli, (std::vector<std::string>{"cryon/office", "stab/office", "vero/office",
                                                   "pencil \"8B\""}));
  ASSERT_EQ(set.triplets.size(), 3u);
  EXPECT_EQ(set.triplets[1].reference, 0u);
  EXPECT_EQ(set.triplets[1].count_a, 2);

  nibrig::test::write_text(dir / "open.csv", "reference,a,b,count_a,count_b\n\"cryon,a,b,1,0\n");
  expect_message_names(format_error_of([&] { read_triplets(dir / "open.csv"); }),
                       {"open.csv", "line 2", "not closed"});
  nibrig::test::write_text(dir / "after.csv", "reference,a,b,count_a,count_b\n\"cryon\"x,a,b,1,0\n");
  expect_message_names(format_error_of([&] { read_triplets(dir / "after.csv"); }),
                       {"after.csv", "line 2", "closing quote"});
}

// The experiment view's own log, as the panel's "Fit a space from judgments" is given it.
TEST(Triplets, AStudySessionsResponsesAreJudgmentsWithoutPractice) {
  const auto dir = nibrig::test::scratch_dir("triplets_responses") / "participants" / "P07";
  std::filesystem::create_directories(dir);
  nibrig::test::write_text(dir / "responses.csv",
                           "trial,practice,stage,reference,left,right,chosen,response_s,plays,answered_utc\n"
                           "1,1,1,chalk,pencil,crayon,left,2.0,RAB,2026-11-26T04:00:00Z\n"
                           "2,0,1,crayon,chalk,pencil,right,1.5,RAB,2026-11-26T04:00:05Z\n"
                           "3,0,1,pencil,crayon,chalk,left,1.1,RA,2026-11-26T04:00:09Z\n"
                           "4,0,2,crayon,pencil,cha");  // cut off by a crash: dropped
  const TripletSet set = read_triplets(dir / "responses.csv");
  EXPECT_EQ(set.stimuli, (std::vector<std::string>{"crayon", "chalk", "pencil"}));
  ASSERT_EQ(set.triplets.size(), 2u) << "practice and the cut-off line are not fitted";
  EXPECT_EQ(set.triplets[0].count_a, 0);
  EXPECT_EQ(set.triplets[0].count_b, 1);
  EXPECT_EQ(set.triplets[1].count_a, 1);
  EXPECT_EQ(set.triplets[1].observer, "P07");
  nibrig::test::write_text(dir / "practice_only.csv",
                           "trial,practice,stage,reference,left,right,chosen,response_s,plays,answered_utc\n"
                           "1,1,1,chalk,pencil,crayon,left,2.0,RAB,2026-11-26T04:00:00Z\n");
  expect_message_names(format_error_of([&] { read_triplets(dir / "practice_only.csv"); }),
                       {"practice_only.csv", "no main answer"});
}

TEST(Triplets, WriterRefusesWhatTheFormatCannotHold) {
  const auto dir = nibrig::test::scratch_dir("triplets_writer");
  TripletSet out_of_range{{"a", "b"}, {{0, 1, 2, 1, 0, ""}}, {}};
  expect_message_names(format_error_of([&] { write_triplet_csv(dir / "t.csv", out_of_range); }),
                       {"t.csv", "triplet 0", "index 2 out of range (2 stimuli)"});
  TripletSet comma{{"a,b", "c", "d"}, {{0, 1, 2, 1, 0, ""}}, {}};
  expect_message_names(format_error_of([&] { write_triplet_csv(dir / "t.csv", comma); }),
                       {"stimulus 0", "without ','"});
  EXPECT_FALSE(std::filesystem::exists(dir / "t.csv"));
}

class TripletCsvMalformed : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = nibrig::test::scratch_dir("triplets_malformed"); }
  std::filesystem::path write(const std::string& body, const std::string& name = "triplets.csv") {
    nibrig::test::write_text(dir_ / name, body);
    return dir_ / name;
  }
  std::filesystem::path dir_;
};

TEST_F(TripletCsvMalformed, TruncatedGzip) {
  std::string body = "reference,a,b,count_a,count_b,observer\n";
  for (int i = 0; i < 20000; ++i) {
    // Appended piece by piece: GCC 12 -O3 warns falsely (-Wrestrict) on "s" + std::to_string(...).
    body += 's';
    body += std::to_string(i * 7919 % 1000) + ",t" + std::to_string(i * 104729 % 997) + ",u" +
            std::to_string(i % 991) + "," + std::to_string(i % 7 + 1) + "," +
            std::to_string(i % 5) + ",o" + std::to_string(i * 31 % 1009) + "\n";
  }
  nibrig::test::write_truncated_gzip(dir_ / "cut.csv.gz", body, 0.5);
  expect_message_names(format_error_of([&] { read_triplet_csv(dir_ / "cut.csv.gz"); }),
                       {"cut.csv.gz", "line ", "compressed data is truncated"});
}

TEST_F(TripletCsvMalformed, NonNumericAndNaNCounts) {
  const auto text = write("reference,a,b,count_a,count_b\nx,y,z,two,1\n");
  expect_message_names(
      format_error_of([&] { read_triplet_csv(text); }),
      {"triplets.csv", "line 2, field 'count_a'", "expected a whole number, found 'two'"});
  const auto nan = write("reference,a,b,count_a,count_b\nx,y,z,1,nan\n", "nan.csv");
  expect_message_names(
      format_error_of([&] { read_triplet_csv(nan); }),
      {"nan.csv", "line 2, field 'count_b'", "expected a whole number, found 'nan'"});
}

TEST_F(TripletCsvMalformed, MissingColumn) {
  const auto file = write("reference,a,b,count_a\nx,y,z,1\n");
  expect_message_names(
      format_error_of([&] { read_triplet_csv(file); }),
      {"triplets.csv", "line 1", "missing column 'count_b'", "reference,a,b,count_a,count_b"});
}

TEST_F(TripletCsvMalformed, EmptyFile) {
  const auto file = write("");
  expect_message_names(format_error_of([&] { read_triplet_csv(file); }),
                       {"triplets.csv", "empty file", "reference,a,b,count_a,count_b"});
  expect_message_names(format_error_of([&] { read_triplets(file); }),
                       {"triplets.csv", "empty file"});
}

TEST_F(TripletCsvMalformed, SelfTripletNegativeAndZeroCounts) {
  const auto self = write("reference,a,b,count_a,count_b\nx,y,z,1,0\nx,x,z,1,0\n");
  expect_message_names(format_error_of([&] { read_triplet_csv(self); }),
                       {"triplets.csv", "line 3", "expected three different stimuli"});
  const auto negative = write("reference,a,b,count_a,count_b\nx,y,z,-1,3\n", "negative.csv");
  expect_message_names(
      format_error_of([&] { read_triplet_csv(negative); }),
      {"negative.csv", "line 2, field 'count_a'", "expected a count >= 0, found -1"});
  const auto zero = write("reference,a,b,count_a,count_b\nx,y,z,0,0\n", "zero.csv");
  expect_message_names(format_error_of([&] { read_triplet_csv(zero); }),
                       {"zero.csv", "line 2", "expected at least one response"});
  const auto short_row = write("reference,a,b,count_a,count_b\nx,y,z,1\n", "short.csv");
  expect_message_names(format_error_of([&] { read_triplet_csv(short_row); }),
                       {"short.csv", "line 2", "expected 5 fields", "found 4"});
}

TEST(LagunasMalformed, ErrorsNameTheJsonPath) {
  const auto dir = nibrig::test::scratch_dir("lagunas_malformed");
  const auto write = [&](const std::string& body) {
    nibrig::test::write_text(dir / "answers.json", body);
    return dir / "answers.json";
  };
  expect_message_names(format_error_of([&] { read_lagunas_json(write("")); }),
                       {"answers.json", "empty file"});
  expect_message_names(
      format_error_of(
          [&] { read_lagunas_json(write("{\"answers\": [[0,1,2]],\n\"agreement\": [[1,0]")); }),
      {"answers.json", "line 2", "invalid JSON"});
  expect_message_names(format_error_of([&] { read_lagunas_json(write("{\"answers\": []}")); }),
                       {"answers.json", "field 'agreement'", "missing field"});
  expect_message_names(
      format_error_of([&] {
        read_lagunas_json(write("{\"answers\": [[0,1,2],[0,1]], \"agreement\": [[1,0],[1,0]]}"));
      }),
      {"field 'answers[1]'", "expected [reference, candidate1, candidate2], found 2 values"});
  expect_message_names(
      format_error_of([&] {
        read_lagunas_json(write("{\"answers\": [[0,1,\"x\"]], \"agreement\": [[1,0]]}"));
      }),
      {"field 'answers[0][2]'", "expected a whole number"});
  expect_message_names(
      format_error_of(
          [&] { read_lagunas_json(write("{\"answers\": [[0,1,2]], \"agreement\": [[-1,2]]}")); }),
      {"field 'agreement[0][0]'", "expected a whole number in [0, "});
  expect_message_names(
      format_error_of(
          [&] { read_lagunas_json(write("{\"answers\": [[0,1,2]], \"agreement\": [[0,0]]}")); }),
      {"field 'agreement[0]'", "expected at least one response"});
  expect_message_names(
      format_error_of(
          [&] { read_lagunas_json(write("{\"answers\": [[3,1,3]], \"agreement\": [[1,0]]}")); }),
      {"field 'answers[0]'", "expected three different stimuli"});
  expect_message_names(
      format_error_of([&] {
        read_lagunas_json(write("{\"answers\": [[0,1,2]], \"agreement\": [[1,0], [2,2]]}"));
      }),
      {"field 'agreement'", "expected one entry per answer (1), found 2"});

  // With names beside the file, an id beyond the list is out of range.
  nibrig::test::write_text(dir / "material_names_sorted.txt", "gold\nsilver\nwood\n");
  expect_message_names(
      format_error_of(
          [&] { read_lagunas_json(write("{\"answers\": [[0,1,5]], \"agreement\": [[1,0]]}")); }),
      {"field 'answers[0][2]'",
       "stimulus id 5 out of range (3 names in material_names_sorted.txt)"});
  const TripletSet named =
      read_lagunas_json(write("{\"answers\": [[0,1,2]], \"agreement\": [[1,3]]}"));
  EXPECT_EQ(named.stimuli, (std::vector<std::string>{"gold", "silver", "wood"}));
  nibrig::test::write_text(dir / "material_names_sorted.txt", "gold\ngold\n");
  expect_message_names(format_error_of([&] { read_lagunas_json(dir / "answers.json"); }),
                       {"material_names_sorted.txt", "line 2", "expected unique names"});

  // Names given override the file beside; without looking beside, the ids stay numbers.
  nibrig::test::write_text(dir / "material_names_sorted.txt", "gold\nsilver\nwood\n");
  EXPECT_EQ(read_lagunas_json(dir / "answers.json", {{"a", "b", "c"}, true}).stimuli,
            (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_EQ(read_triplets(dir / "answers.json", {{}, false}).stimuli,
            (std::vector<std::string>{"0", "1", "2"}));
  expect_message_names(format_error_of([&] {
                         read_lagunas_json(dir / "answers.json", {{"a", "b"}, false});
                       }),
                       {"field 'answers[0][2]'", "stimulus id 2 out of range (2 names given)"});
  try {
    read_lagunas_json(dir / "answers.json", {{"a", "b", "a"}, false});
    ADD_FAILURE() << "a name given twice was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("names: 'a' is given twice"), std::string::npos)
        << e.what();
  }
}

TEST(SalmonMalformed, AnswerMustBeACandidate) {
  const auto dir = nibrig::test::scratch_dir("salmon_malformed");
  nibrig::test::write_text(
      dir / "r.csv",
      "Participant.ID,Timestamp,Center,Left,Right,Answer\n7,t,i1,i2,i3,i2\n7,t,i1,i2,i3,i9\n");
  expect_message_names(format_error_of([&] { read_salmon_csv(dir / "r.csv"); }),
                       {"r.csv", "line 3, field 'Answer'",
                        "expected the Left or the Right item ('i2' or 'i3'), found 'i9'"});
  nibrig::test::write_text(dir / "m.csv", "Participant.ID,Center,Left,Answer\n7,i1,i2,i2\n");
  expect_message_names(format_error_of([&] { read_salmon_csv(dir / "m.csv"); }),
                       {"m.csv", "line 1", "missing column 'Right'"});
  nibrig::test::write_text(dir / "s.csv", "Participant.ID,Center,Left,Right,Answer\n7,i1,i2,i2,i2\n");
  expect_message_names(format_error_of([&] { read_salmon_csv(dir / "s.csv"); }),
                       {"s.csv", "line 2", "expected three different stimuli"});
}

}  // namespace
}  // namespace nibrig::model::io
