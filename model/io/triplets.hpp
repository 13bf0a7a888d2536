// Triplet judgments ("which of a and b is closer to the reference?") with their response counts:
// our own CSV format, plus importers for the Lagunas et al. 2019 JSON and the Salmon responses CSV,
// all producing the same TripletSet for fitting a perceptual space (Sec. 4).
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace nibrig::model::io {

// count_a: how often a was judged closer to the reference than b; count_b the reverse (C_ijk,
// C_jik).
struct Triplet {
  std::size_t reference = 0, a = 0, b = 0;  // indices into TripletSet::stimuli
  int count_a = 0, count_b = 0;
  std::string observer;  // empty when the source does not say
};

struct TripletSet {
  std::vector<std::string> stimuli;
  std::vector<Triplet> triplets;
  std::filesystem::path source;
};

// The sum of count_a + count_b over all triplets.
std::size_t response_count(const TripletSet& set);

// Header `reference,a,b,count_a,count_b[,observer]` (any column order), stimulus names in the first
// three columns; stimuli are numbered in order of first appearance.
TripletSet read_triplet_csv(const std::filesystem::path& file);

// Writes the format read_triplet_csv reads (always with the observer column), through a temporary
// file and a rename. Stimuli that appear in no triplet are not stored. Throws FormatError (naming
// `file` and the triplet) for an invalid set or a name the format cannot hold (',', line breaks).
void write_triplet_csv(const std::filesystem::path& file, const TripletSet& set);

// What Lagunas' numbered stimuli are called: `names` (id k is names[k]) when given; else, with
// `beside_file`, material_names_sorted.txt beside the JSON when present (line k names id k-1; the
// command line's convention); else the ids as text "0", "1", ... The Python module passes its
// `names` argument and never looks beside the file.
struct LagunasNames {
  std::vector<std::string> names;
  bool beside_file = true;
};

// Lagunas et al. 2019: answers[i] = [reference, candidate1, candidate2] (ids 0-99), agreement[i] =
// [times candidate1 chosen, times candidate2 chosen], the ids named as `names` says.
TripletSet read_lagunas_json(const std::filesystem::path& file, const LagunasNames& names = {});

// Salmon responses.csv: one row per response; reference = Center, a = Left, b = Right, the counts
// say which one was the Answer, observer = Participant.ID. Stimuli are the item names, sorted.
TripletSet read_salmon_csv(const std::filesystem::path& file);

// A study session's responses.csv (trial,practice,stage,reference,left,right,chosen,...): each main
// answer one response, practice left out, the observer the participant folder's name.
TripletSet read_response_log_triplets(const std::filesystem::path& file);

// Any of the above, told apart by content: a JSON object is Lagunas', a CSV header with Center and
// Answer is Salmon's, one with reference,left,right,chosen a study's log, one with reference,a,b
// ours.
TripletSet read_triplets(const std::filesystem::path& file, const LagunasNames& names = {});

// The same formats read as triplets to predict (`nibrig space predict`): counts are not used, so a
// triplet with no response (both counts 0) is accepted and our CSV may leave out count_a and
// count_b (read as 0); everything else is checked as above.
TripletSet read_triplet_queries(const std::filesystem::path& file, const LagunasNames& names = {});

}  // namespace nibrig::model::io
