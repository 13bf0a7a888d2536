#include "model/catalog/analysis.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "model/io/format_error.hpp"

namespace nibrig::model::catalog {

namespace {

constexpr double mm_per_m = 1000.0;

std::vector<double> to_mm_s(const std::vector<double>& speeds_m_s) {
  std::vector<double> out;
  out.reserve(speeds_m_s.size());
  for (double v : speeds_m_s) out.push_back(v * mm_per_m);
  return out;
}

nlohmann::json descriptors_json(const measure::VibrationDescriptors& d) {
  nlohmann::json bands = nlohmann::json::object();
  for (const auto& [k, energies] : d.band_energies) bands[std::to_string(k)] = energies;
  return {{"weighted_mean", d.weighted_mean},
          {"weighted_power", d.weighted_power},
          {"band_energies", bands}};
}

std::string relative_name(const std::filesystem::path& path) {
  // Provenance names the file by its last three components (e.g. friction/printed/vero1_...csv.gz):
  // enough to find it in the data set without recording a machine-specific absolute path.
  std::vector<std::string> parts;
  for (const auto& part : path) parts.push_back(part.string());
  const std::size_t keep = std::min<std::size_t>(3, parts.size());
  std::filesystem::path out;
  for (std::size_t i = parts.size() - keep; i < parts.size(); ++i) out /= parts[i];
  return out.string();
}

// The largest jump (ms) between consecutive timestamps inside [begin, end), if one exceeds 10 ms:
// such a window holds samples from either side of a pause. Shorter jumps drop at most 9 of the
// window's 1500 samples (0.6 %), which leaves its spectrum as good as unchanged.
std::optional<long> gap_inside(const io::VibrationRecording& recording, std::size_t begin,
                               std::size_t end) {
  constexpr double jitter_s = 0.010;
  std::optional<long> largest;
  for (std::size_t i : recording.timestamp_gaps) {
    if (i <= begin || i >= end || i >= recording.time_s.size()) continue;
    const double jump_s = recording.time_s[i] - recording.time_s[i - 1];
    if (jump_s <= jitter_s) continue;
    const long jump_ms = std::lround(jump_s * 1000.0);
    if (!largest || jump_ms > *largest) largest = jump_ms;
  }
  return largest;
}

// A recording that reads well but cannot be measured (too short for one sweep, no sliding to fit)
// is the file's fault: the error names it, as a reader's would, instead of naming only the step of
// the pipeline that gave up.
template <typename Work>
auto measuring(const std::filesystem::path& source, Work&& work) {
  try {
    return work();
  } catch (const io::FormatError&) {
    throw;
  } catch (const std::exception& e) {
    throw io::FormatError(source, "", std::string("cannot be measured: ") + e.what());
  }
}

}  // namespace

FrictionAnalysis analyze_friction(const io::FrictionRecording& recording,
                                  const AnalysisOptions& options) {
  FrictionAnalysis analysis;
  analysis.tool = recording.name.tool;
  analysis.surface = recording.name.surface;
  analysis.source = recording.source;
  analysis.normal_load_N = recording.name.normal_load_N;
  analysis.sample_rate_hz = recording.sample_rate_hz;
  analysis.fit = measuring(recording.source, [&] {
    return measure::fit_coulomb_friction(recording.tangential_force_N, recording.sample_rate_hz,
                                         recording.name.normal_load_N, options.sweep);
  });
  analysis.upstream_mu =
      measure::upstream_mu(recording.tangential_force_N, recording.name.normal_load_N);
  analysis.tangential_force_N = recording.tangential_force_N;
  for (const auto& warning : recording.warnings) {
    spdlog::warn("{}: {}", recording.source.string(), warning);
  }
  return analysis;
}

namespace {
// Mean of a speed signal (sample i at i / rate) over [begin_s, end_s); 0 when none falls inside.
double mean_speed_over(const std::vector<double>& speed, double rate, double begin_s, double end_s) {
  const auto first = static_cast<std::size_t>(std::max(0.0, std::ceil(begin_s * rate)));
  const auto last = std::min(speed.size(), static_cast<std::size_t>(std::max(0.0, std::ceil(end_s * rate))));
  if (first >= last) return 0.0;
  double sum = 0.0;
  for (std::size_t i = first; i < last; ++i) sum += speed[i];
  return sum / static_cast<double>(last - first);
}
}  // namespace

VibrationAnalysis analyze_vibration(const io::VibrationRecording& recording,
                                    const measure::ThresholdCurve& threshold,
                                    const AnalysisOptions& options) {
  VibrationAnalysis analysis;
  analysis.tool = recording.name.tool;
  analysis.surface = recording.name.surface;
  analysis.source = recording.source;
  analysis.sample_rate_hz = recording.sample_rate_hz;
  const auto segmentation = measuring(recording.source, [&] {
    return measure::segment_speed_steps(recording.acceleration_m_s2, recording.sample_rate_hz,
                                        options.steps);
  });
  analysis.warnings = recording.warnings;
  analysis.warnings.insert(analysis.warnings.end(), segmentation.warnings.begin(),
                           segmentation.warnings.end());
  for (const auto& step : segmentation.steps) {
    if (const auto gap = gap_inside(recording, step.begin, step.end)) {
      analysis.warnings.push_back("the window of sweep " + std::to_string(step.sweep + 1) +
                                  ", block " + std::to_string(step.block + 1) +
                                  " spans a timestamp jump of " + std::to_string(*gap) +
                                  " ms; its spectrum mixes samples from either side");
    }
  }
  for (const auto& warning : analysis.warnings) {
    spdlog::warn("{}: {}", recording.source.string(), warning);
  }
  analysis.contact_begin = segmentation.contact_begin;
  analysis.steps = segmentation.steps;
  analysis.spectrum = measure::spectrum_per_step(
      recording.acceleration_m_s2, recording.sample_rate_hz, segmentation, options.binning);
  analysis.descriptors =
      measure::compute_vibration_descriptors(analysis.spectrum, threshold, options.max_bands);
  analysis.spectrogram = measure::compute_spectrogram(
      recording.acceleration_m_s2, recording.sample_rate_hz, options.spectrogram);
  return analysis;
}

SessionAnalysis analyze_session(const io::RigSession& session,
                                const measure::ThresholdCurve& threshold,
                                const AnalysisOptions& options) {
  SessionAnalysis analysis;
  analysis.info = session.info;
  analysis.source = session.folder;
  analysis.complete = session.complete;

  if (!session.tangential_force_N.empty()) {
    // A session records the normal force itself, so μ uses the measured load, not the nominal one.
    FrictionAnalysis friction;
    friction.tool = session.info.tool;
    friction.surface = session.info.surface;
    friction.source = session.folder;
    friction.sample_rate_hz = session.info.force_rate_hz;
    friction.tangential_force_N.assign(session.tangential_force_N.begin(),
                                       session.tangential_force_N.end());
    double load = session.info.normal_load_N;
    if (!session.normal_force_N.empty()) {
      double sum = 0.0;
      for (float f : session.normal_force_N) sum += f;
      load = sum / static_cast<double>(session.normal_force_N.size());
    }
    friction.normal_load_N = load;
    // μ divides by the load: one below a pen resting on paper (a session's load of 0, a lifted arm's
    // measured mean, or a damaged 1e-320) makes it meaningless, so friction is not measured and the
    // warning says the load, where it came from and the range μ needs.
    if (!(load >= io::kLightestFrictionLoadN && load <= io::kHeaviestFrictionLoadN)) {
      std::ostringstream why;
      why << "the normal load is " << load << " N ("
          << (session.normal_force_N.empty() ? "session.json normal_load_N" : "the mean of normal_force")
          << "), expected " << io::kLightestFrictionLoadN << " to " << io::kHeaviestFrictionLoadN
          << " N to divide the tangential force by";
      analysis.warnings.push_back("friction not measured: " + why.str());
      spdlog::warn("{}: friction not measured: {}", session.folder.string(), why.str());
    } else {
      // The Coulomb fit finds sliding as a step of the tangential force out of rest. A capture that
      // slides from its first instant (a sweep) has no such step: the session is still measured for
      // its vibration, and the reason friction was not is said.
      try {
        friction.fit = measure::fit_coulomb_friction(friction.tangential_force_N,
                                                     friction.sample_rate_hz, load, options.sweep);
        friction.upstream_mu = std::nan("");
        analysis.friction = std::move(friction);
      } catch (const std::runtime_error& e) {
        analysis.warnings.push_back(std::string("friction not measured: ") + e.what());
        spdlog::warn("{}: friction not measured: {}", session.folder.string(), e.what());
      }
    }
  }

  if (!session.acceleration.empty() && !session.speed_m_s.empty()) {
    VibrationAnalysis vibration;
    vibration.tool = session.info.tool;
    vibration.surface = session.info.surface;
    vibration.source = session.folder;
    vibration.sample_rate_hz = session.info.acceleration_rate_hz;
    // The accelerometer stream is stored as captured; the session's calibration makes it m/s^2.
    const double to_m_s2 = session.info.calibration.accelerometer_m_s2_per_unit;
    std::vector<double> acceleration;
    acceleration.reserve(session.acceleration.size());
    for (float a : session.acceleration) acceleration.push_back(static_cast<double>(a) * to_m_s2);
    const std::vector<double> speed(session.speed_m_s.begin(), session.speed_m_s.end());
    // A capture that held speeds as the paper's protocol does is analysed as the paper analysed its
    // steps (the catalog's method, so the two compare bin for bin); anything else is binned by the
    // measured speed.
    const auto steps = measure::steps_from_profile(
        session.info.profile_time_s, session.info.profile_speed_m_s,
        session.info.acceleration_rate_hz, acceleration.size(), options.steps);
    if (!steps.steps.empty()) {
      for (const auto& step : steps.steps) {
        const double measured = mean_speed_over(speed, session.info.speed_rate_hz,
                                                step.begin / session.info.acceleration_rate_hz,
                                                step.end / session.info.acceleration_rate_hz);
        if (std::abs(measured - step.speed_m_s) > 0.05 * step.speed_m_s + 0.001) {
          vibration.warnings.push_back(
              "the hold at " + std::to_string(step.speed_m_s * 1e3) + " mm/s (block " +
              std::to_string(step.block + 1) + ") measured " + std::to_string(measured * 1e3) +
              " mm/s on the encoder: the motor did not follow the profile");
        }
      }
      for (const auto& warning : vibration.warnings)
        spdlog::warn("{}: {}", session.folder.string(), warning);
      vibration.contact_begin = steps.contact_begin;
      vibration.steps = steps.steps;
      vibration.spectrum = measure::spectrum_per_step(
          acceleration, session.info.acceleration_rate_hz, steps, options.binning);
    } else {
      vibration.spectrum = measure::spectrum_by_speed(
          acceleration, session.info.acceleration_rate_hz, speed, session.info.speed_rate_hz,
          options.session_speed_edges_m_s, options.spectrogram, options.binning);
    }
    vibration.descriptors =
        measure::compute_vibration_descriptors(vibration.spectrum, threshold, options.max_bands);
    vibration.spectrogram = measure::compute_spectrogram(
        acceleration, session.info.acceleration_rate_hz, options.spectrogram);
    analysis.vibration = std::move(vibration);
  }
  if (!analysis.friction && !analysis.vibration) {
    throw std::runtime_error(session.folder.string() +
                             ": session holds neither forces nor acceleration with speed");
  }
  return analysis;
}

io::FrictionDescriptor to_descriptor(const FrictionAnalysis& analysis) {
  io::FrictionDescriptor d;
  d.mu = analysis.fit.mu;
  d.mu_ci_low = analysis.fit.mu_ci_low;
  d.mu_ci_high = analysis.fit.mu_ci_high;
  d.samples = analysis.fit.samples;
  d.speeds_m_s = analysis.fit.speeds_m_s;
  d.mu_by_speed = analysis.fit.mu_by_speed;
  d.provenance.source = relative_name(analysis.source);
  d.provenance.method =
      "Coulomb fit over the detected contact less 1 s at each end (mean tangential/normal force; "
      "95 % interval from the autocorrelation-corrected standard error); normal load " +
      std::to_string(analysis.normal_load_N) + " N";
  return d;
}

io::VibrationDescriptor to_descriptor(const VibrationAnalysis& analysis,
                                      const measure::ThresholdCurve& threshold) {
  io::VibrationDescriptor d;
  d.spectrum = analysis.spectrum;
  d.weighted_mean = analysis.descriptors.weighted_mean;
  d.weighted_power = analysis.descriptors.weighted_power;
  d.band_energies = analysis.descriptors.band_energies;
  d.threshold_curve = threshold.source();
  d.provenance.source = relative_name(analysis.source);
  d.provenance.method =
      "speed steps segmented from the signal; per step a 1.5 s window 0.25 s in, mean removed, "
      "|FFT|*2/N, 5-bin smoothing, averaged over sweeps; weighted by the detection threshold";
  return d;
}

nlohmann::json to_json(const FrictionAnalysis& a) {
  nlohmann::json j;
  j["kind"] = "friction";
  j["tool"] = a.tool;
  j["surface"] = a.surface;
  j["source"] = a.source.string();
  j["normal_load_N"] = a.normal_load_N;
  j["sample_rate_hz"] = a.sample_rate_hz;
  j["mu"] = a.fit.mu;
  j["mu_ci95"] = {a.fit.mu_ci_low, a.fit.mu_ci_high};
  j["samples"] = a.fit.samples;
  j["effective_samples"] = a.fit.effective_samples;
  j["analysed_s"] = {static_cast<double>(a.fit.analysis_begin) / a.sample_rate_hz,
                     static_cast<double>(a.fit.analysis_end) / a.sample_rate_hz};
  j["contact_s"] = {static_cast<double>(a.fit.contact.begin) / a.sample_rate_hz,
                    static_cast<double>(a.fit.contact.end) / a.sample_rate_hz};
  j["speeds_mm_s"] = to_mm_s(a.fit.speeds_m_s);
  j["mu_by_speed"] = a.fit.mu_by_speed;
  j["mu_by_speed_ci95_low"] = a.fit.mu_by_speed_ci_low;
  j["mu_by_speed_ci95_high"] = a.fit.mu_by_speed_ci_high;
  j["mu_slope_per_m_s"] = a.fit.speed_slope_per_m_s;
  if (std::isfinite(a.upstream_mu)) j["upstream_mu"] = a.upstream_mu;
  return j;
}

nlohmann::json to_json(const VibrationAnalysis& a, const measure::ThresholdCurve& threshold) {
  nlohmann::json j;
  j["kind"] = "vibration";
  j["tool"] = a.tool;
  j["surface"] = a.surface;
  j["source"] = a.source.string();
  j["sample_rate_hz"] = a.sample_rate_hz;
  j["frequencies_hz"] = a.spectrum.frequencies_hz;
  j["speeds_mm_s"] = to_mm_s(a.spectrum.speeds_m_s);
  j["amplitude_m_s2"] = a.spectrum.amplitude_m_s2;
  j["descriptors"] = descriptors_json(a.descriptors);
  j["threshold_curve"] = threshold.source();
  nlohmann::json steps = nlohmann::json::array();
  for (const auto& s : a.steps) {
    steps.push_back({{"sweep", s.sweep},
                     {"block", s.block},
                     {"begin_s", static_cast<double>(s.begin) / a.sample_rate_hz},
                     {"end_s", static_cast<double>(s.end) / a.sample_rate_hz},
                     {"speed_mm_s", s.speed_m_s * mm_per_m},
                     {"rms_m_s2", s.rms_m_s2}});
  }
  if (!a.steps.empty()) {
    j["contact_begin_s"] = static_cast<double>(a.contact_begin) / a.sample_rate_hz;
    j["steps"] = steps;
  }
  j["warnings"] = a.warnings;
  return j;
}

nlohmann::json to_json(const SessionAnalysis& a, const measure::ThresholdCurve& threshold) {
  nlohmann::json j;
  j["kind"] = "session";
  j["tool"] = a.info.tool;
  j["surface"] = a.info.surface;
  j["source"] = a.source.string();
  j["complete"] = a.complete;
  if (a.friction) {
    const auto friction = to_json(*a.friction);
    for (const char* key : {"mu", "mu_ci95", "speeds_mm_s", "mu_by_speed"}) {
      j["friction"][key] = friction[key];
    }
    j["mu"] = friction["mu"];
  }
  if (a.vibration) {
    const auto vibration = to_json(*a.vibration, threshold);
    for (const char* key : {"frequencies_hz", "speeds_mm_s", "amplitude_m_s2", "descriptors"}) {
      j[key] = vibration[key];
    }
  }
  return j;
}

}  // namespace nibrig::model::catalog
