// The Python classes nibrig.space.Space, Placement and Judgments, which other areas take and give
// (a design is placed in a Space), as C++ types.
#pragma once

#include <pybind11/pybind11.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/io/triplets.hpp"
#include "model/space/descriptor_map.hpp"
#include "model/space/space_file.hpp"

namespace nibrig::ui::python {

struct Space {
  model::space::SpaceFile file;
  std::vector<std::string> warnings;  // from the fit: e.g. too few stimuli for a descriptor map

  std::size_t index_of(const std::string& name) const {
    for (std::size_t i = 0; i < file.stimuli.size(); ++i)
      if (file.stimuli[i] == name) return i;
    throw std::invalid_argument("'" + name + "' is not a stimulus of this space (it has " +
                                std::to_string(file.stimuli.size()) + ", e.g. '" + file.stimuli.front() + "')");
  }
};

// A position with its uncertainty: a tool placed from descriptors, a design placed from its prediction.
struct Placement {
  model::space::Placement placement;
};

// Judgments read once, for several fits, or made from arrays (`file` empty).
struct Judgments {
  model::io::TripletSet set;
  std::filesystem::path file;
};

// What names judgments made from arrays where a file would be named (a fitted space's provenance,
// an error about a stimulus).
inline constexpr const char* kArraysLabel = "judgments given as arrays";

// The judgments a call takes: Judgments, or a path read here (Lagunas' ids as numbers: Python
// reads no file beside it). Anything else is refused naming `argument`. `label`: the file, or
// kArraysLabel.
model::io::TripletSet judgments_argument(const pybind11::object& given, const char* argument,
                                         std::filesystem::path& label);

// Judgments and read_judgments; Space.evaluate and nibrig.space.validate, added once Space is.
void add_space_judgments(pybind11::module_ m);
void add_space_scores(pybind11::module_ m);

}  // namespace nibrig::ui::python
