#include "model/io/acceleration_trace.hpp"

#include <sndfile.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

#include "model/io/atomic_file.hpp"
#include "model/io/format_error.hpp"
#include "model/io/job_files.hpp"
#include "model/io/rig_session.hpp"
#include "model/io/text_lines.hpp"

namespace nibrig::model::io {
namespace {

constexpr std::size_t kFewestSamples = 16;
constexpr double kStepTolerance = 0.01;  // relative to the median step

AccelerationTrace read_session_trace(const std::filesystem::path& folder) {
  const RigSession session = read_rig_session(folder);
  AccelerationTrace trace;
  trace.sample_rate_hz = session.info.acceleration_rate_hz;
  const double scale = session.info.calibration.accelerometer_m_s2_per_unit;
  trace.acceleration_m_s2.reserve(session.acceleration.size());
  for (float sample : session.acceleration) trace.acceleration_m_s2.push_back(sample * scale);
  if (trace.acceleration_m_s2.size() < kFewestSamples)
    throw FormatError(folder / kAccelerationWav, "",
                      "expected at least 16 samples of acceleration");
  return trace;
}

AccelerationTrace read_csv_trace(const std::filesystem::path& file) {
  CsvReader csv(file, kAccelerationTraceHeader);
  const std::size_t time_column = csv.header().column("time_s");
  const std::size_t value_column = csv.header().column("acceleration_m_s2");
  const std::size_t needed = std::max(time_column, value_column) + 1;
  std::vector<double> times;
  AccelerationTrace trace;
  std::vector<std::string_view> fields;
  std::vector<std::string> warnings;
  std::vector<std::size_t> lines;
  while (csv.next(fields)) {
    if (csv.cut_off_last_row(fields, needed, warnings)) break;
    csv.require_fields(fields, needed);
    const double t = parse_number(fields[time_column], file, csv.line_number(), "time_s");
    const double a =
        parse_number(fields[value_column], file, csv.line_number(), "acceleration_m_s2");
    if (!times.empty() && !(t > times.back()))
      throw FormatError(file, field_place(csv.line_number(), "time_s"),
                        "expected times that increase");
    times.push_back(t);
    lines.push_back(csv.line_number());
    trace.acceleration_m_s2.push_back(a);
  }
  if (times.size() < kFewestSamples)
    throw FormatError(file, "",
                      "expected at least 16 samples, found " + std::to_string(times.size()));
  std::vector<double> steps(times.size() - 1);
  for (std::size_t i = 0; i + 1 < times.size(); ++i) steps[i] = times[i + 1] - times[i];
  std::vector<double> sorted = steps;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2),
                   sorted.end());
  const double median = sorted[sorted.size() / 2];
  for (std::size_t i = 0; i < steps.size(); ++i)
    if (std::abs(steps[i] - median) > kStepTolerance * median) {
      std::ostringstream why;
      why << "expected evenly spaced samples (step " << median << " s), found a step of "
          << steps[i] << " s";
      throw FormatError(file, field_place(lines[i + 1], "time_s"), why.str());
    }
  // The mean step over the whole trace is a better rate estimate than any single rounded step.
  trace.sample_rate_hz = static_cast<double>(times.size() - 1) / (times.back() - times.front());
  return trace;
}

// Closes a trace's WAV on every path out, including exceptions.
struct TraceWavHandle {
  SNDFILE* handle = nullptr;
  ~TraceWavHandle() {
    if (handle != nullptr) sf_close(handle);
  }
};

// An accelerometer recorded through an audio input: one channel, any sample format, in the
// input's full-scale units (libsndfile scales integers to ±1), which the fit's gain absorbs.
AccelerationTrace read_wav_trace(const std::filesystem::path& file) {
  SF_INFO info{};
  TraceWavHandle wav;
  wav.handle = sf_open(file.c_str(), SFM_READ, &info);
  if (wav.handle == nullptr)
    throw FormatError(file, "",
                      std::string("expected a WAV file (libsndfile: ") + sf_strerror(nullptr) + ")");
  note_input(file);
  if (info.channels != 1)
    throw FormatError(file, "header",
                      "expected 1 channel (the accelerometer's), found " +
                          std::to_string(info.channels) +
                          ": save that channel alone, e.g. sox in.wav out.wav remix 1");
  AccelerationTrace trace;
  trace.sample_rate_hz = info.samplerate;
  trace.acceleration_m_s2.resize(static_cast<std::size_t>(std::max<sf_count_t>(info.frames, 0)));
  const sf_count_t got = sf_read_double(wav.handle, trace.acceleration_m_s2.data(), info.frames);
  if (got != info.frames)
    throw FormatError(file, "", "truncated: the header announces " + std::to_string(info.frames) +
                                    " frames, the file holds " + std::to_string(got));
  for (std::size_t i = 0; i < trace.acceleration_m_s2.size(); ++i)
    if (!std::isfinite(trace.acceleration_m_s2[i]))
      throw FormatError(file, "sample " + std::to_string(i), "expected a finite value");
  if (trace.acceleration_m_s2.size() < kFewestSamples)
    throw FormatError(file, "", "expected at least 16 samples, found " +
                                    std::to_string(trace.acceleration_m_s2.size()));
  return trace;
}

}  // namespace

AccelerationTrace read_acceleration_trace(const std::filesystem::path& file_or_session) {
  std::error_code error;
  if (std::filesystem::is_directory(file_or_session, error))
    return read_session_trace(file_or_session);
  std::string extension = file_or_session.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".wav") return read_wav_trace(file_or_session);
  return read_csv_trace(file_or_session);
}

void write_acceleration_trace(const std::filesystem::path& file, const AccelerationTrace& trace) {
  std::ostringstream out;
  out << kAccelerationTraceHeader << "\n" << std::setprecision(10);
  for (std::size_t i = 0; i < trace.acceleration_m_s2.size(); ++i)
    out << static_cast<double>(i) / trace.sample_rate_hz << "," << trace.acceleration_m_s2[i]
        << "\n";
  write_file_atomically(file, out.str());
}

}  // namespace nibrig::model::io
