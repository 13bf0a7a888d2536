// Reader for Salmon's responses.csv (see ../shared/data/salmon_alien_eggs/PROVENANCE.md).
#include <algorithm>
#include <unordered_map>

#include "model/io/format_error.hpp"
#include "model/io/text_lines.hpp"
#include "model/io/triplet_checks.hpp"
#include "model/io/triplets.hpp"

namespace nibrig::model::io {

namespace {

constexpr const char* kSalmonHeader = "Participant.ID,Timestamp,Center,Left,Right,Answer,...";

struct Response {
  std::string center, left, right, observer;
  bool left_chosen = false;
  std::size_t line = 0;
};

}  // namespace

TripletSet read_salmon_csv(const std::filesystem::path& file) {
  CsvReader csv(file, kSalmonHeader);
  const std::size_t c_participant = csv.header().column("Participant.ID");
  const std::size_t c_center = csv.header().column("Center");
  const std::size_t c_left = csv.header().column("Left");
  const std::size_t c_right = csv.header().column("Right");
  const std::size_t c_answer = csv.header().column("Answer");
  const std::size_t needed = std::max({c_participant, c_center, c_left, c_right, c_answer}) + 1;

  std::vector<Response> responses;
  std::vector<std::string_view> fields;
  while (csv.next(fields)) {
    const std::size_t line = csv.line_number();
    csv.require_fields(fields, needed);
    Response response;
    response.line = line;
    response.observer = std::string(fields[c_participant]);
    const std::pair<std::size_t, std::string*> items[] = {
        {c_center, &response.center}, {c_left, &response.left}, {c_right, &response.right}};
    for (const auto& [column, target] : items) {
      if (fields[column].empty()) {
        throw FormatError(file, field_place(line, csv.header().names()[column]),
                          "expected an item name, found an empty field");
      }
      *target = std::string(fields[column]);
    }
    const std::string_view answer = fields[c_answer];
    if (answer != response.left && answer != response.right) {
      throw FormatError(file, field_place(line, "Answer"),
                        "expected the Left or the Right item (" + in_quotes(response.left) +
                            " or " + in_quotes(response.right) + "), found " + in_quotes(answer));
    }
    response.left_chosen = answer == response.left;
    responses.push_back(std::move(response));
  }

  TripletSet set;
  set.source = file;
  for (const Response& r : responses) {
    for (const std::string* name : {&r.center, &r.left, &r.right}) set.stimuli.push_back(*name);
  }
  std::sort(set.stimuli.begin(), set.stimuli.end());
  set.stimuli.erase(std::unique(set.stimuli.begin(), set.stimuli.end()), set.stimuli.end());
  std::unordered_map<std::string, std::size_t> index_of;
  for (std::size_t i = 0; i < set.stimuli.size(); ++i) index_of.emplace(set.stimuli[i], i);

  set.triplets.reserve(responses.size());
  for (Response& r : responses) {
    Triplet triplet;
    triplet.reference = index_of.at(r.center);
    triplet.a = index_of.at(r.left);
    triplet.b = index_of.at(r.right);
    triplet.count_a = r.left_chosen ? 1 : 0;
    triplet.count_b = r.left_chosen ? 0 : 1;
    triplet.observer = std::move(r.observer);
    if (auto problem = triplet_problem(triplet, set.stimuli)) {
      throw FormatError(file, line_place(r.line), *problem);
    }
    set.triplets.push_back(std::move(triplet));
  }
  return set;
}

}  // namespace nibrig::model::io
