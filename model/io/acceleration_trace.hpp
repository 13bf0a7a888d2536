// A single accelerometer trace sampled at a constant rate, as a ring-down test records it: a CSV
// file with columns time_s,acceleration_m_s2 (optionally .csv.gz), a mono WAV recorded through an
// audio input (in its full-scale units: a fit must find the gain), or one of our session folders
// (its acceleration stream, calibrated to m/s²).
#pragma once

#include <filesystem>
#include <vector>

namespace nibrig::model::io {

struct AccelerationTrace {
  double sample_rate_hz = 0.0;
  std::vector<double> acceleration_m_s2;
};

inline constexpr const char* kAccelerationTraceHeader = "time_s,acceleration_m_s2";

// A file ending in .wav (any case) is read as a WAV. Throws FormatError naming the file and line:
// a WAV of several channels, missing column, non-numeric or non-finite value,
// times that do not increase or are not evenly spaced (within 1 % of the median step: a trace with
// gaps cannot be fitted sample by sample), fewer than 16 samples.
AccelerationTrace read_acceleration_trace(const std::filesystem::path& file_or_session);

// Writes the CSV form (times from 0 at the sample rate), atomically.
void write_acceleration_trace(const std::filesystem::path& file, const AccelerationTrace& trace);

}  // namespace nibrig::model::io
