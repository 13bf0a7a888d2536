// The stimuli of a study as an experimenter lists them, one per line: a catalog pairing
// ("crayon/office"), a design point on a surface ("DM85:0.5,vero:0.5,tip=2mm/office"), or either
// under a short name ("D1 = DM85:0.5,vero:0.5,tip=2mm/office"), which the judgments then use.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace nibrig::model::study {

struct Stimulus {
  std::string name;     // as judgments, plans and spaces name it; never holds a ',' (CSV)
  std::string tool;     // a catalog tool id or a design point
  std::string surface;  // a catalog surface id
};

// Blank lines and lines starting with '#' are skipped. `NAME = TOOL/SURFACE` names a stimulus;
// without a name it is called `TOOL/SURFACE`. The surface is what follows the last '/'. Throws
// io::FormatError naming the file and line: no '/' or an empty tool or surface, a name with a
// ',' (a design point needs a short name, which the message suggests), a name listed twice;
// and naming the file for fewer than `minimum` stimuli.
std::vector<Stimulus> read_stimulus_list(const std::filesystem::path& file,
                                         std::size_t minimum = 3);

// The names of a list with no tool/surface form required (`space plan` takes any names): each
// line, trimmed, is the name. Same comments, duplicate and minimum rules.
std::vector<std::string> read_stimulus_names(const std::filesystem::path& file,
                                             std::size_t minimum = 3);

// "tool/surface" of a stimulus: the form a list line without a name takes.
std::string pairing_of(const Stimulus& stimulus);

}  // namespace nibrig::model::study
