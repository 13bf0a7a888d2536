// nibrig.measure: one recording (a friction or accelerometer file of the paper's, or a rig session)
// to μ, the velocity-binned spectrum and the perceptually weighted descriptors, as `nibrig measure`
// gives them (model/catalog/analysis.hpp); a folder of recordings to a catalog, as `nibrig catalog`.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <atomic>
#include <optional>

#include "model/catalog/analysis.hpp"
#include "model/catalog/catalog_builder.hpp"
#include "model/io/bundled_assets.hpp"
#include "model/io/catalog_file.hpp"
#include "model/io/format_error.hpp"
#include "model/io/paper_recording.hpp"
#include "model/io/rig_session.hpp"
#include "model/numeric/cancellation.hpp"
#include "ui/python/long_call.hpp"
#include "ui/python/numpy_views.hpp"
#include "ui/python/pickle_state.hpp"
#include "ui/python/python_log.hpp"
#include "ui/python/submodules.hpp"

namespace nibrig::ui::python {

namespace py = pybind11;
namespace catalog = model::catalog;

namespace {

// What one recording measured, as Python shows it (not the traces the analyses keep for plots);
// the parts its kind has.
struct MeasuredFriction {
  double mu = 0.0, mu_low = 0.0, mu_high = 0.0, normal_load_N = 0.0;
};
struct MeasuredVibration {
  model::io::VelocitySpectrum spectrum;
  model::measure::VibrationDescriptors descriptors;
};
struct Measurement {
  std::string kind;  // "friction", "vibration" or "session"
  std::string tool, surface;
  std::optional<MeasuredFriction> friction;
  std::optional<MeasuredVibration> vibration;
  std::vector<std::string> warnings;
  std::string json;  // what `nibrig measure` writes

  void keep(const catalog::FrictionAnalysis& f) {
    friction = MeasuredFriction{f.fit.mu, f.fit.mu_ci_low, f.fit.mu_ci_high, f.normal_load_N};
  }
  void keep(const catalog::VibrationAnalysis& v) {
    vibration = MeasuredVibration{v.spectrum, v.descriptors};
  }
};

// A measurement pickles as its numbers (a joblib worker's result over many recordings).
py::tuple measurement_state(const Measurement& m) {
  py::object friction = py::none(), vibration = py::none();
  if (m.friction)
    friction = py::make_tuple(m.friction->mu, m.friction->mu_low, m.friction->mu_high,
                              m.friction->normal_load_N);
  if (m.vibration)
    vibration = py::make_tuple(spectrum_state(m.vibration->spectrum),
                               descriptors_state(m.vibration->descriptors));
  return py::make_tuple(m.kind, m.tool, m.surface, friction, vibration, m.warnings, m.json);
}

Measurement measurement_of(const py::tuple& state) {
  const std::string type = "Measurement";
  require_state(state, 7, type);
  Measurement m;
  m.kind = state[0].cast<std::string>();
  m.tool = state[1].cast<std::string>();
  m.surface = state[2].cast<std::string>();
  if (!state[3].is_none()) {
    const auto f = state[3].cast<py::tuple>();
    require_state(f, 4, type);
    m.friction = MeasuredFriction{f[0].cast<double>(), f[1].cast<double>(), f[2].cast<double>(),
                                  f[3].cast<double>()};
  }
  if (!state[4].is_none()) {
    const auto v = state[4].cast<py::tuple>();
    require_state(v, 2, type);
    m.vibration = MeasuredVibration{spectrum_of(v[0], type), descriptors_of(v[1], type)};
  }
  m.warnings = state[5].cast<std::vector<std::string>>();
  m.json = state[6].cast<std::string>();
  return m;
}

model::measure::ThresholdCurve threshold_of(const std::optional<std::filesystem::path>& file) {
  return model::measure::ThresholdCurve::load(file.value_or(model::io::default_threshold_curve()));
}

Measurement measure_recording(const std::filesystem::path& recording, const std::optional<std::string>& tool,
                              const std::optional<std::string>& surface, const std::optional<double>& load,
                              const std::optional<double>& lever, const std::optional<std::filesystem::path>& threshold_file) {
  ReleasedGil unlocked;
  std::error_code ec;
  if (!std::filesystem::exists(recording, ec))  // FileNotFoundError, as a reader's own refusal would be
    throw model::io::FormatError(recording, "", "no such file or folder");
  const auto threshold = threshold_of(threshold_file);
  const catalog::AnalysisOptions options;
  const model::io::StatedRecording stated{tool, surface, load, lever};
  Measurement m;
  switch (catalog::classify_recording_by_content(recording)) {
    case catalog::RecordingKind::paper_friction: {
      m.kind = "friction";
      const auto friction =
          catalog::analyze_friction(model::io::read_paper_friction(recording, stated), options);
      m.tool = friction.tool, m.surface = friction.surface;
      m.keep(friction);
      m.json = catalog::to_json(friction).dump(2);
      break;
    }
    case catalog::RecordingKind::paper_vibration: {
      m.kind = "vibration";
      const auto vibration = catalog::analyze_vibration(
          model::io::read_paper_vibration(recording, stated), threshold, options);
      m.tool = vibration.tool, m.surface = vibration.surface;
      m.warnings = vibration.warnings;
      m.keep(vibration);
      m.json = catalog::to_json(vibration, threshold).dump(2);
      break;
    }
    case catalog::RecordingKind::session: {
      if (tool || surface || load || lever)
        throw std::invalid_argument(recording.string() +
                                    ": a rig session names its own tool, surface and load; tool, surface, load "
                                    "and lever are for single CSV recordings");
      const auto a = catalog::analyze_session(model::io::read_rig_session(recording), threshold, options);
      m.kind = "session";
      m.tool = a.info.tool, m.surface = a.info.surface;
      if (a.friction) m.keep(*a.friction);
      if (a.vibration) m.keep(*a.vibration);
      m.warnings = a.warnings;
      m.json = catalog::to_json(a, threshold).dump(2);
      break;
    }
  }
  return m;
}

const MeasuredVibration& vibration_of(const Measurement& m) {
  if (!m.vibration) throw std::invalid_argument("this " + m.kind + " recording has no vibration spectrum");
  return *m.vibration;
}

const MeasuredFriction& friction_of(const Measurement& m) {
  if (!m.friction) throw std::invalid_argument("this " + m.kind + " recording has no friction");
  return *m.friction;
}

struct Catalog {
  model::io::Catalog catalog;
  std::vector<std::string> skipped;
};

constexpr const char* kPickledCatalog = "a pickled nibrig.measure.Catalog";

Catalog build(const std::filesystem::path& folder, const std::optional<std::filesystem::path>& threshold_file,
              unsigned threads, const py::object& progress) {
  Catalog out;
  run_long_call(
      [&](std::stop_token stop, const Report& report) {
        const auto threshold = threshold_of(threshold_file);
        const auto found = catalog::find_recordings(folder);
        std::atomic<std::size_t> done{0};
        const std::size_t total = found.files.size();
        const catalog::AnalysisOptions options;
        auto built = catalog::build_catalog(found, threshold, options, threads,
                                            [&](const std::filesystem::path&) {
                                              report("analysing recordings", ++done, total);
                                              model::numeric::throw_if_cancelled(stop, "catalog build");
                                            });
        out.catalog = std::move(built.catalog);
        out.skipped = std::move(built.skipped);
      },
      progress);
  return out;
}

}  // namespace

void add_measure_module(py::module_ m) {
  py::class_<Measurement>(m, "Measurement", "One recording's physical descriptors (Sec. 3 and 4.4)")
      .def_readonly("kind", &Measurement::kind, "'friction', 'vibration' or 'session'")
      .def_readonly("tool", &Measurement::tool)
      .def_readonly("surface", &Measurement::surface)
      .def_readonly("warnings", &Measurement::warnings)
      .def_property_readonly(
          "mu", [](const Measurement& m) { return friction_of(m).mu; },
          "The Coulomb coefficient: mean tangential over normal force while sliding")
      .def_property_readonly(
          "mu_interval",
          [](const Measurement& m) {
            return std::pair(friction_of(m).mu_low, friction_of(m).mu_high);
          },
          "μ's 95 % confidence interval (its samples' autocorrelation accounted for)")
      .def_property_readonly("normal_load_N",
                             [](const Measurement& m) { return friction_of(m).normal_load_N; })
      .def_property_readonly(
          "frequencies_hz",
          [](const py::object& self) {
            const auto& v = vibration_of(self.cast<const Measurement&>()).spectrum.frequencies_hz;
            return array_view(v.data(), v.size(), self);
          },
          "The spectrum's frequencies, Hz (a view)")
      .def_property_readonly(
          "speeds_m_s",
          [](const py::object& self) {
            const auto& v = vibration_of(self.cast<const Measurement&>()).spectrum.speeds_m_s;
            return array_view(v.data(), v.size(), self);
          },
          "The speeds the spectrum is binned at, m/s (a view)")
      .def_property_readonly(
          "amplitude",
          [](const Measurement& m) { return spectrum_array(vibration_of(m).spectrum); },
          "The velocity-binned spectrum, speeds x frequencies, m/s² (a copy: rows are separate "
          "vectors)")
      .def_property_readonly(
          "weighted_mean",
          [](const Measurement& m) { return vibration_of(m).descriptors.weighted_mean; },
          "Mean of the threshold-weighted spectrum: the descriptor of the paper's 2-D space "
          "(dimensionless)")
      .def_property_readonly(
          "weighted_power",
          [](const Measurement& m) { return vibration_of(m).descriptors.weighted_power; },
          "Mean over speeds of the weighted spectrum's power, Hz")
      .def_property_readonly(
          "band_energies",
          [](const Measurement& m) { return vibration_of(m).descriptors.band_energies; },
          "k -> the weighted power in k equal bands (they add up to weighted_power)")
      .def(
          "to_json", [](const Measurement& m) { return m.json; },
          "What `nibrig measure` writes for it")
      .def(py::pickle(&measurement_state, &measurement_of));

  m.def("recording", &measure_recording, py::arg("path"), py::kw_only(), py::arg("tool") = py::none(),
        py::arg("surface") = py::none(), py::arg("load") = py::none(), py::arg("lever") = py::none(),
        py::arg("threshold") = py::none(),
        "Measures one recording as `nibrig measure` does: a friction file "
        "(<tool>_<surface>_<load>N_<lever>_<rep>.csv[.gz]), an accelerometer file (arm_<tool>_<surface>.csv[.gz]) "
        "or a rig session folder. A file named otherwise takes tool, surface and, for friction, load (N) and "
        "lever. threshold: the detection-threshold curve weighting the spectrum (default: the bundled one).");

  py::class_<Catalog>(m, "Catalog",
                      "Tools and surfaces with their friction and vibration descriptors")
      .def_property_readonly("tools",
                             [](const Catalog& c) {
                               std::vector<std::string> ids;
                               for (const auto& t : c.catalog.tools) ids.push_back(t.id);
                               return ids;
                             })
      .def_property_readonly("surfaces",
                             [](const Catalog& c) {
                               std::vector<std::string> ids;
                               for (const auto& s : c.catalog.surfaces) ids.push_back(s.id);
                               return ids;
                             })
      .def_property_readonly(
          "pairings",
          [](const Catalog& c) {
            py::list out;
            for (const auto& p : c.catalog.pairings) {
              py::dict d;
              d["tool"] = p.tool, d["surface"] = p.surface;
              d["mu"] = p.friction ? py::cast(p.friction->mu) : py::none();
              d["weighted_mean"] = p.vibration ? py::cast(p.vibration->weighted_mean) : py::none();
              out.append(d);
            }
            return out;
          },
          "Each tool/surface pair with its μ and weighted mean vibration (None where not measured)")
      .def_readonly("skipped", &Catalog::skipped,
                    "Files of the folder that are not recordings, with why")
      .def(
          "save",
          [](const Catalog& c, const std::filesystem::path& file) {
            ReleasedGil unlocked;
            model::io::write_catalog(file, c.catalog);
          },
          py::arg("path"), "Writes the catalog JSON (`nibrig catalog -o`), atomically")
      .def(py::pickle(
          [](const Catalog& c) {
            return py::make_tuple(model::io::catalog_text(c.catalog, kPickledCatalog), c.skipped);
          },
          [](const py::tuple& state) {
            require_state(state, 2, "Catalog");
            return Catalog{model::io::parse_catalog(state[0].cast<std::string>(), kPickledCatalog),
                           state[1].cast<std::vector<std::string>>()};
          }));

  m.def("catalog", &build, py::arg("folder"), py::kw_only(), py::arg("threshold") = py::none(),
        py::arg("threads") = 0u, py::arg("progress") = py::none(),
        "Every recording under a folder measured into one catalog, as `nibrig catalog` does; progress: "
        "(step, done, total) per file. Releases the GIL; Ctrl-C stops it.");
  m.def(
      "load_catalog",
      [](const std::filesystem::path& file) {
        ReleasedGil unlocked;
        return Catalog{model::io::read_catalog(file), {}};
      },
      py::arg("path"), "Reads a catalog JSON (the bundled one: nibrig.measure.bundled_catalog())");
  m.def("bundled_catalog", [] { return model::io::default_catalog(); },
        "The path of the catalog bundled with nibrig (derived from the paper's recordings)");
}

}  // namespace nibrig::ui::python
