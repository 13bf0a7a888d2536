// nibrig.space.Judgments: triplet judgments from arrays (stimulus indices with answers or counts,
// the names a list of their own) or read from a file once; both ways out again, and pickled.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <string>

#include "model/io/triplet_checks.hpp"
#include "model/io/triplets.hpp"
#include "ui/python/pickle_state.hpp"
#include "ui/python/python_log.hpp"
#include "ui/python/space_types.hpp"

namespace nibrig::ui::python {

namespace py = pybind11;
namespace io = model::io;

namespace {

// An integer array of `columns` columns (or 1-D for 0), refusing floats, which would truncate.
py::array_t<long long> integer_array(const py::handle& given, const char* name, py::ssize_t rows,
                                     int columns) {
  const py::array a = py::array::ensure(given);
  if (!a) throw py::type_error(std::string(name) + ": expected an array of integers");
  const char kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u' && kind != 'b')
    throw py::type_error(std::string(name) + ": expected integers, found an array of dtype " +
                         std::string(py::str(a.dtype())));
  const bool shaped = columns == 0 ? a.ndim() == 1 : a.ndim() == 2 && a.shape(1) == columns;
  if (!shaped || (rows >= 0 && a.shape(0) != rows))
    throw std::invalid_argument(std::string(name) + ": expected shape (" +
                                (rows >= 0 ? std::to_string(rows) : std::string("n")) +
                                (columns == 0 ? ",)" : ", " + std::to_string(columns) + ")") +
                                ", found " + std::string(py::str(py::getattr(a, "shape"))));
  return py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(a);
}

Judgments judgments_from_arrays(const py::handle& triplets,
                                const std::optional<std::vector<std::string>>& stimuli,
                                const py::object& answers, const py::object& counts) {
  if (!answers.is_none() && !counts.is_none())
    throw std::invalid_argument(
        "answers and counts: give one (answers: one per triplet; counts: (n, 2))");
  const auto t = integer_array(triplets, "triplets", -1, 3);
  const auto rows = t.shape(0);
  const auto index = t.unchecked<2>();
  Judgments j;
  j.set.source = kArraysLabel;
  long long largest = -1;
  for (py::ssize_t r = 0; r < rows; ++r)
    for (int c = 0; c < 3; ++c) {
      const long long v = index(r, c);
      if (v < 0 || (stimuli && v >= static_cast<long long>(stimuli->size())))
        throw std::invalid_argument(
            "triplets[" + std::to_string(r) + ", " + std::to_string(c) + "]: " + std::to_string(v) +
            " is not a stimulus index (expected 0 to " +
            (stimuli ? std::to_string(stimuli->size()) + " - 1, one per name in stimuli"
                     : std::string("the number of stimuli - 1")) +
            ")");
      largest = std::max(largest, v);
    }
  if (stimuli) {
    j.set.stimuli = *stimuli;
  } else {
    for (long long k = 0; k <= largest; ++k) j.set.stimuli.push_back(std::to_string(k));
  }
  py::array_t<long long> a, c;
  if (!answers.is_none()) a = integer_array(answers, "answers", rows, 0);
  if (!counts.is_none()) c = integer_array(counts, "counts", rows, 2);
  for (py::ssize_t r = 0; r < rows; ++r) {
    io::Triplet triplet;
    triplet.reference = static_cast<std::size_t>(index(r, 0));
    triplet.a = static_cast<std::size_t>(index(r, 1));
    triplet.b = static_cast<std::size_t>(index(r, 2));
    if (!answers.is_none()) {
      const long long v = a.unchecked<1>()(r);
      if (v != 0 && v != 1)
        throw std::invalid_argument(
            "answers[" + std::to_string(r) + "]: " + std::to_string(v) +
            "; expected 1 (the first candidate judged closer) or 0 (the second)");
      (v == 1 ? triplet.count_a : triplet.count_b) = 1;
    } else if (!counts.is_none()) {
      const auto n = c.unchecked<2>();
      for (int k = 0; k < 2; ++k)
        if (n(r, k) < 0 || n(r, k) > std::numeric_limits<int>::max())
          throw std::invalid_argument("counts[" + std::to_string(r) + ", " + std::to_string(k) +
                                      "]: " + std::to_string(n(r, k)) +
                                      "; expected a number of answers, 0 or more");
      triplet.count_a = static_cast<int>(n(r, 0));
      triplet.count_b = static_cast<int>(n(r, 1));
    } else {
      triplet.count_a = 1;  // each row is (reference, the closer, the farther)
    }
    if (const auto problem = io::triplet_problem(triplet, j.set.stimuli))
      throw std::invalid_argument("triplets[" + std::to_string(r) + "]: " + *problem);
    j.set.triplets.push_back(triplet);
  }
  return j;
}

py::array_t<long long> triplet_indices(const Judgments& j) {
  py::array_t<long long> out({static_cast<py::ssize_t>(j.set.triplets.size()), py::ssize_t{3}});
  auto o = out.mutable_unchecked<2>();
  for (std::size_t r = 0; r < j.set.triplets.size(); ++r) {
    const auto& t = j.set.triplets[r];
    const auto i = static_cast<py::ssize_t>(r);
    o(i, 0) = static_cast<long long>(t.reference), o(i, 1) = static_cast<long long>(t.a),
         o(i, 2) = static_cast<long long>(t.b);
  }
  return out;
}

py::array_t<long long> triplet_counts(const Judgments& j) {
  py::array_t<long long> out({static_cast<py::ssize_t>(j.set.triplets.size()), py::ssize_t{2}});
  auto o = out.mutable_unchecked<2>();
  for (std::size_t r = 0; r < j.set.triplets.size(); ++r) {
    o(static_cast<py::ssize_t>(r), 0) = j.set.triplets[r].count_a;
    o(static_cast<py::ssize_t>(r), 1) = j.set.triplets[r].count_b;
  }
  return out;
}

std::vector<std::string> observers(const Judgments& j) {
  std::vector<std::string> out;
  for (const auto& t : j.set.triplets) out.push_back(t.observer);
  return out;
}

}  // namespace

io::TripletSet judgments_argument(const py::object& given, const char* argument,
                                  std::filesystem::path& label) {
  if (py::isinstance<Judgments>(given)) {
    const auto& j = given.cast<const Judgments&>();
    label = j.file.empty() ? std::filesystem::path(kArraysLabel) : j.file;
    return j.set;
  }
  if (!py::isinstance<py::str>(given) &&
      !py::isinstance(given, py::module_::import("os").attr("PathLike")))
    throw py::type_error(std::string(argument) +
                         ": expected Judgments (from arrays or read_judgments) or a file "
                         "path, found " +
                         std::string(py::str(given.get_type().attr("__name__"))));
  label = given.cast<std::filesystem::path>();
  ReleasedGil unlocked;
  return io::read_triplets(label, {{}, false});
}

void add_space_judgments(py::module_ m) {
  py::class_<Judgments>(
      m, "Judgments",
      "Triplet judgments: which of two candidates is closer to a reference, as arrays or read "
      "from a file once, for several fits")
      .def(py::init([](const py::handle& triplets,
                       const std::optional<std::vector<std::string>>& stimuli,
                       const py::object& answers, const py::object& counts) {
             return judgments_from_arrays(triplets, stimuli, answers, counts);
           }),
           py::arg("triplets"), py::arg("stimuli") = py::none(), py::kw_only(),
           py::arg("answers") = py::none(), py::arg("counts") = py::none(),
           "Judgments from arrays. triplets: (n, 3) integer indices (reference, first candidate, "
           "second "
           "candidate) into `stimuli`, a list of names (default: '0', '1', ... up to the largest "
           "index). "
           "answers: n values, 1 (True) where the first candidate was judged closer to the "
           "reference, 0 "
           "where the second was; counts: (n, 2), how often each candidate was judged closer "
           "(repeated "
           "queries); neither: each row is already (reference, the closer, the farther).")
      .def_property_readonly(
          "stimuli", [](const Judgments& j) { return j.set.stimuli; },
          "The stimuli's names; the triplets' indices point into this list")
      .def_property_readonly(
          "triplets", &triplet_indices,
          "(n, 3) integer array: the reference's, the first and the second candidate's "
          "indices into stimuli (a copy)")
      .def_property_readonly(
          "counts", &triplet_counts,
          "(n, 2) integer array: how often the first and the second candidate was judged "
          "closer (a copy)")
      .def_property_readonly(
          "observers", &observers,
          "Who answered each triplet, where the source says ('' where it does not)")
      .def_property_readonly(
          "responses", [](const Judgments& j) { return io::response_count(j.set); },
          "All answers: the sum of counts")
      .def_property_readonly(
          "file",
          [](const Judgments& j) -> py::object {
            return j.file.empty() ? py::none() : py::cast(j.file);
          },
          "The file they were read from; None for arrays")
      .def("__len__", [](const Judgments& j) { return j.set.triplets.size(); })
      .def("__repr__",
           [](const Judgments& j) {
             return "<nibrig.space.Judgments: " + std::to_string(j.set.triplets.size()) +
                    " triplets, " + std::to_string(io::response_count(j.set)) + " answers, " +
                    std::to_string(j.set.stimuli.size()) + " stimuli" +
                    (j.file.empty() ? std::string() : " from " + j.file.string()) + ">";
           })
      .def(py::pickle(
          [](const Judgments& j) {
            return py::make_tuple(triplet_indices(j), j.set.stimuli, triplet_counts(j),
                                  observers(j), j.file.string());
          },
          [](const py::tuple& state) {
            require_state(state, 5, "Judgments");
            Judgments j = judgments_from_arrays(state[0], state[1].cast<std::vector<std::string>>(),
                                                py::none(), state[2]);
            const auto who = state[3].cast<std::vector<std::string>>();
            for (std::size_t r = 0; r < who.size() && r < j.set.triplets.size(); ++r)
              j.set.triplets[r].observer = who[r];
            j.file = state[4].cast<std::string>();
            if (!j.file.empty()) j.set.source = j.file;
            return j;
          }));

  m.def(
      "read_judgments",
      [](const std::filesystem::path& file, const std::optional<std::vector<std::string>>& names) {
        ReleasedGil unlocked;
        return Judgments{
            io::read_triplets(file, {names.value_or(std::vector<std::string>{}), false}), file};
      },
      py::arg("path"), py::kw_only(), py::arg("names") = py::none(),
      "Reads triplet judgments (the paper's, Lagunas', Salmon's formats, a study's answers) once, "
      "for several "
      "fits. names: what Lagunas' numbered stimuli are called (id k is names[k]); without it they "
      "are '0', "
      "'1', ... (nothing beside the file is read)");
}

}  // namespace nibrig::ui::python
