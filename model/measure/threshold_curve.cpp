#include "model/measure/threshold_curve.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "model/io/format_error.hpp"
#include "model/io/text_lines.hpp"

namespace nibrig::model::measure {

namespace {

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r\n");
  if (a == std::string::npos) return "";
  const auto b = s.find_last_not_of(" \t\r\n");
  return s.substr(a, b - a + 1);
}

// Whole-field number parse: "12.5" yes, "12.5x", "" and "nan" no.
bool parse_number(const std::string& field, double& value) {
  const std::string t = trim(field);
  if (t.empty()) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(t.c_str(), &end);
  return errno == 0 && end == t.c_str() + t.size() && std::isfinite(value);
}

// Empty string when the table is valid, else what is wrong and at which row (0-based).
std::string table_problem(const std::vector<double>& f, const std::vector<double>& t,
                          std::size_t& row) {
  if (f.size() != t.size()) return "frequency and threshold columns differ in length";
  if (f.size() < 2) {
    row = f.size();
    return "at least 2 rows are needed for interpolation";
  }
  for (row = 0; row < f.size(); ++row) {
    if (!(f[row] > 0.0) || !std::isfinite(f[row])) return "frequency must be positive";
    if (!(t[row] > 0.0) || !std::isfinite(t[row])) return "threshold must be positive";
    if (row > 0 && !(f[row] > f[row - 1])) return "frequencies must increase strictly";
  }
  return "";
}

}  // namespace

ThresholdCurve::ThresholdCurve(std::vector<double> frequencies_hz,
                               std::vector<double> thresholds_m_s2, std::string source)
    : frequencies_(std::move(frequencies_hz)),
      thresholds_(std::move(thresholds_m_s2)),
      source_(std::move(source)) {
  std::size_t row = 0;
  const std::string problem = table_problem(frequencies_, thresholds_, row);
  if (!problem.empty()) {
    throw std::invalid_argument("threshold curve row " + std::to_string(row) + ": " + problem);
  }
}

ThresholdCurve ThresholdCurve::load(const std::filesystem::path& csv) {
  io::TextLineReader in(csv);
  std::vector<double> frequencies, thresholds;
  std::vector<std::size_t> lines;
  std::string source;
  bool header_seen = false;
  std::string line;
  while (in.next(line)) {
    const std::size_t number = in.line_number();
    const std::string t = trim(line);
    if (t.empty()) continue;
    if (t[0] == '#') {
      const std::string comment = trim(t.substr(1));
      if (comment.rfind("source:", 0) == 0) {
        if (!source.empty()) source += ' ';
        source += trim(comment.substr(7));
      }
      continue;
    }
    const auto comma = t.find(',');
    if (!header_seen) {
      if (comma == std::string::npos || trim(t.substr(0, comma)) != "frequency_hz" ||
          trim(t.substr(comma + 1)) != "threshold_m_s2") {
        throw io::FormatError(csv, io::line_place(number),
                              "expected the header 'frequency_hz,threshold_m_s2'");
      }
      header_seen = true;
      continue;
    }
    if (comma == std::string::npos || t.find(',', comma + 1) != std::string::npos) {
      throw io::FormatError(csv, io::line_place(number), "expected 2 comma-separated fields");
    }
    double f = 0.0, thr = 0.0;
    if (!parse_number(t.substr(0, comma), f)) {
      throw io::FormatError(csv, io::field_place(number, "frequency_hz"), "not a finite number");
    }
    if (!parse_number(t.substr(comma + 1), thr)) {
      throw io::FormatError(csv, io::field_place(number, "threshold_m_s2"), "not a finite number");
    }
    frequencies.push_back(f);
    thresholds.push_back(thr);
    lines.push_back(number);
  }
  if (!header_seen) throw io::FormatError(csv, "", "no header line 'frequency_hz,threshold_m_s2'");
  std::size_t row = 0;
  const std::string problem = table_problem(frequencies, thresholds, row);
  if (!problem.empty()) {
    const std::string place = row < lines.size() ? io::line_place(lines[row]) : "";
    throw io::FormatError(csv, place, problem);
  }
  if (source.empty())
    throw io::FormatError(csv, "", "no '# source:' comment naming the data's origin");
  return ThresholdCurve(std::move(frequencies), std::move(thresholds), std::move(source));
}

double ThresholdCurve::threshold_m_s2(double frequency_hz) const {
  if (std::isnan(frequency_hz) || frequency_hz < 0.0) {
    throw std::invalid_argument("threshold curve: frequency must be a non-negative number");
  }
  if (frequency_hz <= frequencies_.front()) return thresholds_.front();
  if (frequency_hz >= frequencies_.back()) return thresholds_.back();
  const auto upper = std::upper_bound(frequencies_.begin(), frequencies_.end(), frequency_hz);
  const auto i = static_cast<std::size_t>(upper - frequencies_.begin());
  const double x0 = std::log(frequencies_[i - 1]), x1 = std::log(frequencies_[i]);
  const double y0 = std::log(thresholds_[i - 1]), y1 = std::log(thresholds_[i]);
  const double u = (std::log(frequency_hz) - x0) / (x1 - x0);
  return std::exp(y0 + u * (y1 - y0));
}

std::vector<std::vector<double>> weight_by_threshold(const io::VelocitySpectrum& spectrum,
                                                     const ThresholdCurve& curve) {
  std::vector<double> thresholds(spectrum.frequencies_hz.size());
  for (std::size_t f = 0; f < thresholds.size(); ++f) {
    thresholds[f] = curve.threshold_m_s2(spectrum.frequencies_hz[f]);
  }
  std::vector<std::vector<double>> ratio;
  ratio.reserve(spectrum.amplitude_m_s2.size());
  for (const auto& row : spectrum.amplitude_m_s2) {
    if (row.size() != thresholds.size()) {
      throw std::invalid_argument("weight_by_threshold: a speed row has " +
                                  std::to_string(row.size()) + " amplitudes for " +
                                  std::to_string(thresholds.size()) + " frequencies");
    }
    std::vector<double> r(row.size());
    for (std::size_t f = 0; f < row.size(); ++f) r[f] = row[f] / thresholds[f];
    ratio.push_back(std::move(r));
  }
  return ratio;
}

}  // namespace nibrig::model::measure
