// One recording in, its physical descriptors out: the measurement pipeline of Sec. 3 and 4.4
// applied to a friction recording (contact, Coulomb μ with its interval, μ against speed), an
// accelerometer recording (speed steps, velocity-binned spectrum, perceptually weighted
// descriptors) or a rig session.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "model/io/catalog_file.hpp"
#include "model/io/paper_friction.hpp"
#include "model/io/paper_vibration.hpp"
#include "model/io/rig_session.hpp"
#include "model/measure/descriptors.hpp"
#include "model/measure/friction.hpp"
#include "model/measure/spectrogram.hpp"
#include "model/measure/step_segmentation.hpp"
#include "model/measure/threshold_curve.hpp"
#include "model/measure/velocity_binning.hpp"

namespace nibrig::model::catalog {

struct AnalysisOptions {
  measure::StepProtocol steps;
  measure::BinningSettings binning;
  measure::SweepAssumption sweep;
  measure::SpectrogramSettings spectrogram{.segment_length = 512, .hop = 128};
  int max_bands = 5;
  // Speed bins for recordings that carry a continuous speed signal (rig sessions), m/s.
  std::vector<double> session_speed_edges_m_s{0.017, 0.056, 0.095, 0.134, 0.173, 0.211, 0.250};
};

struct FrictionAnalysis {
  std::string tool, surface;
  std::filesystem::path source;
  double normal_load_N = 0.0;
  double sample_rate_hz = 0.0;
  measure::FrictionFit fit;
  double upstream_mu = 0.0;  // the authors' recipe, for comparison (see measure::upstream_mu)
  std::vector<double> tangential_force_N;  // the whole trace, for plots
};

struct VibrationAnalysis {
  std::string tool, surface;
  std::filesystem::path source;
  double sample_rate_hz = 0.0;
  std::vector<std::string> warnings;
  std::size_t contact_begin = 0;
  std::vector<measure::SpeedStep> steps;
  io::VelocitySpectrum spectrum;
  measure::VibrationDescriptors descriptors;
  measure::Spectrogram spectrogram;  // of the whole recording, for plots
};

FrictionAnalysis analyze_friction(const io::FrictionRecording& recording,
                                  const AnalysisOptions& options);

VibrationAnalysis analyze_vibration(const io::VibrationRecording& recording,
                                    const measure::ThresholdCurve& threshold,
                                    const AnalysisOptions& options);

// A rig session has its own speed signal (binned continuously) and both force components.
struct SessionAnalysis {
  io::RigSessionInfo info;
  std::filesystem::path source;
  bool complete = true;
  std::optional<FrictionAnalysis> friction;
  std::optional<VibrationAnalysis> vibration;
  std::vector<std::string> warnings;  // what could not be measured, and why
};

SessionAnalysis analyze_session(const io::RigSession& session,
                                const measure::ThresholdCurve& threshold,
                                const AnalysisOptions& options);

// The descriptors in the catalog's terms, with their provenance.
io::FrictionDescriptor to_descriptor(const FrictionAnalysis& analysis);
io::VibrationDescriptor to_descriptor(const VibrationAnalysis& analysis,
                                      const measure::ThresholdCurve& threshold);

// The JSON written by `nibrig measure`: `mu` for friction; `frequencies_hz`, `speeds_mm_s` and
// `amplitude_m_s2` for the velocity-binned spectrum, plus the descriptors and how they were found.
nlohmann::json to_json(const FrictionAnalysis& analysis);
nlohmann::json to_json(const VibrationAnalysis& analysis, const measure::ThresholdCurve& threshold);
nlohmann::json to_json(const SessionAnalysis& analysis, const measure::ThresholdCurve& threshold);

}  // namespace nibrig::model::catalog
