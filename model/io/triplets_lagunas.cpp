// Reader for the Lagunas et al. 2019 triplet JSON (see ../shared/data/lagunas2019/PROVENANCE.md).
#include <algorithm>
#include <climits>
#include <unordered_set>

#include "model/io/format_error.hpp"
#include "model/io/json_fields.hpp"
#include "model/io/text_lines.hpp"
#include "model/io/triplet_checks.hpp"
#include "model/io/triplets.hpp"

namespace nibrig::model::io {

namespace {

constexpr const char* kNamesFile = "material_names_sorted.txt";
// Without a names file every id up to the largest becomes a stimulus; this keeps a corrupt id from
// creating millions of them (the real data has 100).
constexpr long long kMaxIdWithoutNames = 99'999;

std::vector<std::string> read_names(const std::filesystem::path& file) {
  TextLineReader lines(file);
  std::vector<std::string> names;
  std::unordered_set<std::string> seen;
  std::string line;
  std::size_t first_blank = 0;
  while (lines.next(line)) {
    if (line.find_first_not_of(" \t") == std::string::npos) {
      if (first_blank == 0) first_blank = lines.line_number();
      continue;
    }
    if (first_blank != 0) {
      throw FormatError(file, line_place(first_blank),
                        "expected a material name, found a blank line");
    }
    if (!seen.insert(line).second) {
      throw FormatError(file, line_place(lines.line_number()),
                        "expected unique names, found " + in_quotes(line) + " a second time");
    }
    names.push_back(line);
  }
  if (names.empty()) throw FormatError(file, "", "empty file: expected one material name per line");
  return names;
}

}  // namespace

TripletSet read_lagunas_json(const std::filesystem::path& file, const LagunasNames& names) {
  return read_lagunas_json(file, Responses::required, names);
}

TripletSet read_lagunas_json(const std::filesystem::path& file, Responses responses,
                             const LagunasNames& given) {
  using namespace json_fields;
  const nlohmann::json json = parse_file(file);
  const nlohmann::json& answers = as_array(member(json, "answers", file, ""), file, "answers");
  const nlohmann::json& agreement =
      as_array(member(json, "agreement", file, ""), file, "agreement");
  if (answers.size() != agreement.size()) {
    throw FormatError(file, place("agreement"),
                      "expected one entry per answer (" + std::to_string(answers.size()) +
                          "), found " + std::to_string(agreement.size()));
  }

  TripletSet set;
  set.source = file;
  const std::filesystem::path names_file = file.parent_path() / kNamesFile;
  std::error_code ec;
  const bool beside =
      given.names.empty() && given.beside_file && std::filesystem::is_regular_file(names_file, ec);
  const bool named = beside || !given.names.empty();
  if (beside) set.stimuli = read_names(names_file);
  if (!given.names.empty()) {
    std::unordered_set<std::string> seen;
    for (const auto& name : given.names)
      if (!seen.insert(name).second)
        throw std::invalid_argument("names: " + in_quotes(name) +
                                    " is given twice; expected one name per stimulus id");
    set.stimuli = given.names;
  }
  const long long max_id =
      named ? static_cast<long long>(set.stimuli.size()) - 1 : kMaxIdWithoutNames;
  const std::string id_range_reason =
      beside  ? " (" + std::to_string(set.stimuli.size()) + " names in " + kNamesFile + ")"
      : named ? " (" + std::to_string(set.stimuli.size()) + " names given)"
              : "";

  long long largest = -1;
  set.triplets.reserve(answers.size());
  for (std::size_t i = 0; i < answers.size(); ++i) {
    const std::string answer_path = element_path("answers", i);
    const std::string agreement_path = element_path("agreement", i);
    const nlohmann::json& ids = as_array(answers[i], file, answer_path);
    const nlohmann::json& counts = as_array(agreement[i], file, agreement_path);
    if (ids.size() != 3) {
      throw FormatError(file, place(answer_path),
                        "expected [reference, candidate1, candidate2], found " +
                            std::to_string(ids.size()) + " values");
    }
    if (counts.size() != 2) {
      throw FormatError(
          file, place(agreement_path),
          "expected [count1, count2], found " + std::to_string(counts.size()) + " values");
    }
    long long id[3];
    for (std::size_t k = 0; k < 3; ++k) {
      const std::string path = element_path(answer_path, k);
      if (ids[k].is_number_integer() && named && ids[k].get<long long>() > max_id) {
        throw FormatError(file, place(path),
                          "stimulus id " + ids[k].dump() + " out of range" + id_range_reason);
      }
      id[k] = as_integer(ids[k], file, path, 0, max_id);
      largest = std::max(largest, id[k]);
    }
    Triplet triplet;
    triplet.reference = static_cast<std::size_t>(id[0]);
    triplet.a = static_cast<std::size_t>(id[1]);
    triplet.b = static_cast<std::size_t>(id[2]);
    triplet.count_a =
        static_cast<int>(as_integer(counts[0], file, element_path(agreement_path, 0), 0, INT_MAX));
    triplet.count_b =
        static_cast<int>(as_integer(counts[1], file, element_path(agreement_path, 1), 0, INT_MAX));
    if (responses == Responses::required && triplet.count_a == 0 && triplet.count_b == 0) {
      throw FormatError(file, place(agreement_path),
                        "expected at least one response, found [0, 0]");
    }
    set.triplets.push_back(triplet);
  }
  if (!named) {
    for (long long k = 0; k <= largest; ++k) set.stimuli.push_back(std::to_string(k));
  }
  for (std::size_t i = 0; i < set.triplets.size(); ++i) {
    if (auto problem = triplet_problem(set.triplets[i], set.stimuli, responses)) {
      throw FormatError(file, place(element_path("answers", i)), *problem);
    }
  }
  return set;
}

}  // namespace nibrig::model::io
