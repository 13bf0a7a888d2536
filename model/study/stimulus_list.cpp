#include "model/study/stimulus_list.hpp"

#include <set>

#include "model/io/format_error.hpp"
#include "model/io/text_lines.hpp"

namespace nibrig::model::study {
namespace {

std::string trim_list_text(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// Every listed line, trim_list_text, with its line number; comments and blank lines left out.
struct StimulusListLine {
  std::string text;
  std::size_t line = 0;
};

std::vector<StimulusListLine> stimulus_list_lines(const std::filesystem::path& file) {
  io::TextLineReader reader(file);
  std::vector<StimulusListLine> lines;
  std::string line;
  while (reader.next(line)) {
    std::string text = trim_list_text(line);
    if (text.empty() || text.front() == '#') continue;
    lines.push_back({std::move(text), reader.line_number()});
  }
  return lines;
}

void check_stimulus_names(const std::filesystem::path& file, const std::vector<std::string>& names,
                             const std::vector<StimulusListLine>& lines, std::size_t minimum) {
  std::set<std::string> seen;
  for (std::size_t i = 0; i < names.size(); ++i)
    if (!seen.insert(names[i]).second)
      throw io::FormatError(file, io::line_place(lines[i].line),
                            "stimulus '" + names[i] + "' is listed twice");
  if (names.size() < minimum)
    throw io::FormatError(file, "",
                          "expected at least " + std::to_string(minimum) +
                              " stimuli, one per line, found " + std::to_string(names.size()));
}

}  // namespace

std::string pairing_of(const Stimulus& stimulus) { return stimulus.tool + "/" + stimulus.surface; }

std::vector<Stimulus> read_stimulus_list(const std::filesystem::path& file, std::size_t minimum) {
  const std::vector<StimulusListLine> lines = stimulus_list_lines(file);
  std::vector<Stimulus> stimuli;
  std::vector<std::string> names;
  for (const auto& [text, line] : lines) {
    const auto equals = text.find('=');
    // A design point holds "tip=2mm": only an '=' before the first ':' or ',' names a stimulus.
    const bool named = equals != std::string::npos && text.find_first_of(":,") > equals;
    Stimulus s;
    const std::string spec = named ? trim_list_text(text.substr(equals + 1)) : text;
    const auto slash = spec.rfind('/');
    if (slash == std::string::npos || slash == 0 || slash + 1 == spec.size())
      throw io::FormatError(file, io::line_place(line),
                            "expected TOOL/SURFACE or NAME = TOOL/SURFACE, found " +
                                io::in_quotes(text));
    s.tool = trim_list_text(spec.substr(0, slash));
    s.surface = trim_list_text(spec.substr(slash + 1));
    s.name = named ? trim_list_text(text.substr(0, equals)) : pairing_of(s);
    if (s.name.empty())
      throw io::FormatError(file, io::line_place(line), "empty name before '='");
    if (s.name.find(',') != std::string::npos)
      throw io::FormatError(
          file, io::line_place(line),
          "the name " + io::in_quotes(s.name) +
              " holds a ',', which judgment files cannot: give it a short name, as in 'D1 = " +
              spec + "'");
    names.push_back(s.name);
    stimuli.push_back(std::move(s));
  }
  check_stimulus_names(file, names, lines, minimum);
  return stimuli;
}

std::vector<std::string> read_stimulus_names(const std::filesystem::path& file,
                                             std::size_t minimum) {
  const std::vector<StimulusListLine> lines = stimulus_list_lines(file);
  std::vector<std::string> names;
  for (const auto& l : lines) names.push_back(l.text);
  check_stimulus_names(file, names, lines, minimum);
  return names;
}

}  // namespace nibrig::model::study
