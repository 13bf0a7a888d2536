// A study session's responses.csv (model/study/response_log.hpp) read as judgments, so that the log
// the experiment view writes can be fitted directly (the panel's "Fit a space from judgments"
// refused it). Each main answer is one response; practice is never fitted.
#include <algorithm>
#include <unordered_map>

#include "model/io/format_error.hpp"
#include "model/io/text_lines.hpp"
#include "model/io/triplet_checks.hpp"
#include "model/io/triplets.hpp"

namespace nibrig::model::io {

namespace {
constexpr const char* kResponseLogHeader =
    "trial,practice,stage,reference,left,right,chosen,response_s,plays,answered_utc";
}  // namespace

bool is_response_log_header(const CsvHeader& header) {
  for (const char* column : {"practice", "reference", "left", "right", "chosen"})
    if (!header.find(column)) return false;
  return true;
}

TripletSet read_response_log_triplets(const std::filesystem::path& file) {
  CsvReader csv(file, kResponseLogHeader);
  const CsvHeader& h = csv.header();
  const std::size_t c_practice = h.column("practice"), c_reference = h.column("reference"),
                    c_left = h.column("left"), c_right = h.column("right"), c_chosen = h.column("chosen");
  const std::size_t needed = std::max({c_practice, c_reference, c_left, c_right, c_chosen}) + 1;
  // The participant's folder names them: <study>/participants/<ID>/responses.csv.
  const std::string observer = std::filesystem::absolute(file).parent_path().filename().string();
  TripletSet set;
  set.source = file;
  std::unordered_map<std::string, std::size_t> index_of;
  std::vector<std::string_view> fields;
  while (csv.next(fields)) {
    if (csv.row_unterminated()) break;  // cut off by a crash: the session drops it too
    const std::size_t line = csv.line_number();
    csv.require_fields(fields, needed);
    if (fields[c_practice] != "0" && fields[c_practice] != "1")
      throw FormatError(file, field_place(line, "practice"), "expected 0 or 1, found " + in_quotes(fields[c_practice]));
    if (fields[c_practice] == "1") continue;
    std::size_t indices[3] = {};
    const std::size_t columns[3] = {c_reference, c_left, c_right};
    for (int k = 0; k < 3; ++k) {
      const std::string name(fields[columns[k]]);
      if (name.empty())
        throw FormatError(file, field_place(line, h.names()[columns[k]]), "expected a stimulus name, found an empty field");
      indices[k] = index_of.emplace(name, set.stimuli.size()).first->second;
      if (indices[k] == set.stimuli.size()) set.stimuli.push_back(name);
    }
    const std::string_view chosen = fields[c_chosen];
    if (chosen != "left" && chosen != "right")
      throw FormatError(file, field_place(line, "chosen"), "expected left or right, found " + in_quotes(chosen));
    Triplet triplet{indices[0], indices[1], indices[2], chosen == "left" ? 1 : 0, chosen == "left" ? 0 : 1, observer};
    if (auto problem = triplet_problem(triplet, set.stimuli)) throw FormatError(file, line_place(line), *problem);
    set.triplets.push_back(std::move(triplet));
  }
  if (set.triplets.empty())
    throw FormatError(file, "", "a study session's answers with no main answer yet: nothing to fit");
  return set;
}

}  // namespace nibrig::model::io
