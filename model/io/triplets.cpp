#include "model/io/triplets.hpp"

#include <algorithm>
#include <climits>
#include <optional>
#include <unordered_map>

#include "model/io/atomic_file.hpp"
#include "model/io/format_error.hpp"
#include "model/io/text_lines.hpp"
#include "model/io/triplet_checks.hpp"

namespace nibrig::model::io {

namespace {

constexpr const char* kTripletHeader = "reference,a,b,count_a,count_b[,observer]";

std::string name_or_index(std::size_t index, const std::vector<std::string>& stimuli) {
  if (index < stimuli.size()) return in_quotes(stimuli[index]);
  std::string text = "#";  // appended, not "#" + ...: GCC 12 -O3 warns falsely (-Wrestrict) on that
  return text.append(std::to_string(index));
}

// Text the CSV cannot hold: the separator, or a line break (a trailing '\r' would be eaten as
// CRLF).
bool storable(const std::string& text) { return text.find_first_of(",\n\r") == std::string::npos; }

}  // namespace

std::optional<std::string> triplet_problem(const Triplet& triplet,
                                           const std::vector<std::string>& stimuli,
                                           Responses responses) {
  for (std::size_t index : {triplet.reference, triplet.a, triplet.b}) {
    if (index >= stimuli.size()) {
      return "index " + std::to_string(index) + " out of range (" + std::to_string(stimuli.size()) +
             " stimuli)";
    }
  }
  if (triplet.reference == triplet.a || triplet.reference == triplet.b || triplet.a == triplet.b) {
    return "expected three different stimuli, found reference " +
           name_or_index(triplet.reference, stimuli) + ", a " + name_or_index(triplet.a, stimuli) +
           ", b " + name_or_index(triplet.b, stimuli);
  }
  if (triplet.count_a < 0 || triplet.count_b < 0) {
    return "expected counts >= 0, found " + std::to_string(triplet.count_a) + " and " +
           std::to_string(triplet.count_b);
  }
  if (responses == Responses::required && triplet.count_a == 0 && triplet.count_b == 0) {
    return "expected at least one response, found counts 0 and 0";
  }
  return std::nullopt;
}

std::size_t response_count(const TripletSet& set) {
  std::size_t total = 0;
  for (const Triplet& t : set.triplets) {
    total += static_cast<std::size_t>(t.count_a) + static_cast<std::size_t>(t.count_b);
  }
  return total;
}

TripletSet read_triplet_csv(const std::filesystem::path& file) {
  return read_triplet_csv(file, Responses::required);
}

TripletSet read_triplet_csv(const std::filesystem::path& file, Responses responses) {
  CsvReader csv(file, kTripletHeader);
  const std::size_t columns[] = {csv.header().column("reference"), csv.header().column("a"),
                                 csv.header().column("b")};
  const char* column_names[] = {"reference", "a", "b"};
  // Triplets to predict (Responses::optional) need no answers, so a file of reference,a,b alone is
  // read with both counts 0; judgments must have both columns (column() throws naming the file).
  const auto count_column = [&](const char* name) -> std::optional<std::size_t> {
    if (responses == Responses::optional) return csv.header().find(name);
    return csv.header().column(name);
  };
  const std::optional<std::size_t> c_count_a = count_column("count_a");
  const std::optional<std::size_t> c_count_b = count_column("count_b");
  const auto c_observer = csv.header().find("observer");
  std::size_t needed = std::max({columns[0], columns[1], columns[2]}) + 1;
  for (const auto& c : {c_count_a, c_count_b, c_observer})
    if (c) needed = std::max(needed, *c + 1);

  TripletSet set;
  set.source = file;
  std::unordered_map<std::string, std::size_t> index_of;
  std::vector<std::string_view> fields;
  while (csv.next(fields)) {
    const std::size_t line = csv.line_number();
    csv.require_fields(fields, needed);
    std::size_t indices[3] = {};
    for (int k = 0; k < 3; ++k) {
      const std::string name(fields[columns[k]]);
      if (name.empty()) {
        throw FormatError(file, field_place(line, column_names[k]),
                          "expected a stimulus name, found an empty field");
      }
      auto [it, inserted] = index_of.emplace(name, set.stimuli.size());
      if (inserted) set.stimuli.push_back(name);
      indices[k] = it->second;
    }
    Triplet triplet;
    triplet.reference = indices[0];
    triplet.a = indices[1];
    triplet.b = indices[2];
    const long long count_a = c_count_a ? parse_integer(fields[*c_count_a], file, line, "count_a") : 0;
    const long long count_b = c_count_b ? parse_integer(fields[*c_count_b], file, line, "count_b") : 0;
    for (const auto& [count, column] :
         {std::pair{count_a, "count_a"}, std::pair{count_b, "count_b"}}) {
      if (count < 0 || count > INT_MAX) {
        throw FormatError(file, field_place(line, column),
                          "expected a count >= 0, found " + std::to_string(count));
      }
    }
    triplet.count_a = static_cast<int>(count_a);
    triplet.count_b = static_cast<int>(count_b);
    if (c_observer) triplet.observer = std::string(fields[*c_observer]);
    if (auto problem = triplet_problem(triplet, set.stimuli, responses)) {
      throw FormatError(file, line_place(line), *problem);
    }
    set.triplets.push_back(std::move(triplet));
  }
  return set;
}

void write_triplet_csv(const std::filesystem::path& file, const TripletSet& set) {
  for (std::size_t s = 0; s < set.stimuli.size(); ++s) {
    if (set.stimuli[s].empty() || !storable(set.stimuli[s])) {
      throw FormatError(file, "stimulus " + std::to_string(s),
                        "expected a non-empty name without ',' or line breaks, found " +
                            in_quotes(set.stimuli[s]));
    }
  }
  std::string text = "reference,a,b,count_a,count_b,observer\n";
  for (std::size_t i = 0; i < set.triplets.size(); ++i) {
    const Triplet& t = set.triplets[i];
    if (auto problem = triplet_problem(t, set.stimuli)) {
      throw FormatError(file, "triplet " + std::to_string(i), *problem);
    }
    if (!storable(t.observer)) {
      throw FormatError(
          file, "triplet " + std::to_string(i),
          "expected an observer without ',' or line breaks, found " + in_quotes(t.observer));
    }
    text += set.stimuli[t.reference] + ',' + set.stimuli[t.a] + ',' + set.stimuli[t.b] + ',' +
            std::to_string(t.count_a) + ',' + std::to_string(t.count_b) + ',' + t.observer + '\n';
  }
  write_file_atomically(file, text);
}

namespace {

TripletSet read_any_triplets(const std::filesystem::path& file, Responses responses,
                             const LagunasNames& names) {
  if (file.extension() == ".json") return read_lagunas_json(file, responses, names);
  std::string first;
  {
    TextLineReader lines(file);
    if (!lines.next(first)) {
      throw FormatError(file, "",
                        "empty file: expected a triplet CSV header " +
                            std::string(kTripletHeader) + " or a JSON object");
    }
  }
  const std::size_t start = first.find_first_not_of(" \t\xEF\xBB\xBF");
  if (start != std::string::npos && first[start] == '{')
    return read_lagunas_json(file, responses, names);
  const CsvHeader header(first, file, 1, kTripletHeader);
  if (header.find("Center") && header.find("Answer")) return read_salmon_csv(file);
  if (is_response_log_header(header)) return read_response_log_triplets(file);
  if (header.find("reference")) return read_triplet_csv(file, responses);
  throw FormatError(
      file, line_place(1),
      "unrecognised triplet file: expected a header " + std::string(kTripletHeader) +
          " (nibrig), one with Participant.ID,Center,Left,Right,Answer (Salmon), a study's "
          "responses.csv, or a "
          "JSON object with answers and agreement (Lagunas et al.), found " +
          in_quotes(first));
}

}  // namespace

TripletSet read_triplets(const std::filesystem::path& file, const LagunasNames& names) {
  return read_any_triplets(file, Responses::required, names);
}

TripletSet read_triplet_queries(const std::filesystem::path& file, const LagunasNames& names) {
  return read_any_triplets(file, Responses::optional, names);
}

}  // namespace nibrig::model::io
