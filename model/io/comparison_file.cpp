#include "model/io/comparison_file.hpp"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "model/io/atomic_file.hpp"
#include "model/io/format_error.hpp"
#include "model/io/json_fields.hpp"
#include "model/io/finite_output.hpp"

namespace nibrig::model::io {
namespace {

namespace jf = json_fields;
using nlohmann::json;

constexpr const char* kComparisonFormat = "nibrig-comparison";
constexpr long long kComparisonVersion = 1;
constexpr double kMmPerM = 1000.0;  // speeds are mm/s in files, m/s inside
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr long long kMaxCount = std::numeric_limits<long long>::max();

// JSON has no NaN: a value that does not exist is null.
json number_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

struct Reader {
  const std::filesystem::path& file;

  double number(const json& object, const std::string& key, const std::string& parent) const {
    return jf::number_member(object, key, file, parent);
  }
  // A number, or NaN for null.
  double number_or_nan(const json& object, const std::string& key,
                       const std::string& parent) const {
    const json& v = jf::member(object, key, file, parent);
    return v.is_null() ? kNaN : jf::as_number(v, file, jf::member_path(parent, key));
  }
  std::uint64_t count(const json& object, const std::string& key, const std::string& parent) const {
    return static_cast<std::uint64_t>(jf::as_integer(jf::member(object, key, file, parent), file,
                                                     jf::member_path(parent, key), 0, kMaxCount));
  }
  [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
    throw FormatError(file, jf::place(path), problem);
  }
};

}  // namespace

void write_comparison_file(const ComparisonFile& c, const std::filesystem::path& file) {
  json bins = json::array();
  for (const auto& b : c.bins) {
    bins.push_back(
        {{"min_speed_mm_s", b.min_speed_m_s * kMmPerM},
         {"max_speed_mm_s", b.max_speed_m_s * kMmPerM},
         {"mean_speed_mm_s", number_or_null(b.mean_speed_m_s * kMmPerM)},
         {"rows", b.rows},
         {"lsd_db", number_or_null(b.lsd_db)},
         {"measured_weighted_mean", number_or_null(b.measured_weighted_mean)},
         {"simulated_weighted_mean", number_or_null(b.simulated_weighted_mean)},
         {"weighted_mean_log10_difference", number_or_null(b.weighted_mean_log10_difference)}});
  }
  json j = {{"format", kComparisonFormat},
            {"version", kComparisonVersion},
            {"tool", c.tool},
            {"surface", c.surface},
            {"spectrogram",
             {{"sample_rate_hz", c.sample_rate_hz},
              {"segment_length", c.segment_length},
              {"hop", c.hop},
              {"window", c.window}}},
            {"band_hz", {c.band_min_hz, c.band_max_hz}},
            {"speed_bins", bins},
            {"overall",
             {{"bins_with_rows", c.bins_with_rows},
              {"rows", c.rows},
              {"rows_outside_speed_range", c.rows_outside_speed_range},
              {"mean_lsd_db", number_or_null(c.mean_lsd_db)},
              {"mean_weighted_mean_log10_difference",
               number_or_null(c.mean_weighted_mean_log10_difference)}}},
            {"capture",
             {{"rows_analysed", c.rows_analysed},
              {"rows_without_speed", c.rows_without_speed},
              {"blocks_dropped", c.blocks_dropped}}}};
  j["actuator"] = nullptr;
  if (c.actuator)
    j["actuator"] = {{"contacts", c.actuator->contacts},
                     {"follow_mean_ms", c.actuator->follow_mean_s * 1e3},
                     {"follow_max_ms", c.actuator->follow_max_s * 1e3},
                     {"period_ms", c.actuator->period_s * 1e3}};
  write_file_atomically(file, json_text(j, file));
}

ComparisonFile read_comparison_file(const std::filesystem::path& file) {
  const json root = jf::parse_file(file);
  jf::as_object(root, file, "");
  jf::check_format_and_version(root, file, kComparisonFormat, kComparisonVersion);
  const Reader r{file};
  ComparisonFile c;
  c.tool = jf::string_member(root, "tool", file, "");
  c.surface = jf::string_member(root, "surface", file, "");

  const json& sg = jf::as_object(jf::member(root, "spectrogram", file, ""), file, "spectrogram");
  c.sample_rate_hz = r.number(sg, "sample_rate_hz", "spectrogram");
  if (!(c.sample_rate_hz > 0)) r.fail("spectrogram.sample_rate_hz", "expected a positive rate");
  c.segment_length = static_cast<std::uint64_t>(
      jf::as_integer(jf::member(sg, "segment_length", file, "spectrogram"), file,
                     "spectrogram.segment_length", 2, kMaxCount));
  c.hop = static_cast<std::uint64_t>(jf::as_integer(jf::member(sg, "hop", file, "spectrogram"),
                                                    file, "spectrogram.hop", 1, kMaxCount));
  c.window = jf::string_member(sg, "window", file, "spectrogram");
  if (c.window != "hann" && c.window != "rectangular")
    r.fail("spectrogram.window",
           "expected \"hann\" or \"rectangular\", found \"" + c.window + "\"");

  const std::vector<double> band =
      jf::as_number_array(jf::member(root, "band_hz", file, ""), file, "band_hz");
  if (band.size() != 2 || !(band[0] >= 0) || !(band[1] > band[0]))
    r.fail("band_hz", "expected [min, max] with 0 <= min < max");
  c.band_min_hz = band[0];
  c.band_max_hz = band[1];

  const json& bins = jf::as_array(jf::member(root, "speed_bins", file, ""), file, "speed_bins");
  for (std::size_t i = 0; i < bins.size(); ++i) {
    const std::string at = jf::element_path("speed_bins", i);
    const json& b = jf::as_object(bins[i], file, at);
    ComparisonBin bin;
    bin.min_speed_m_s = r.number(b, "min_speed_mm_s", at) / kMmPerM;
    bin.max_speed_m_s = r.number(b, "max_speed_mm_s", at) / kMmPerM;
    if (!(bin.min_speed_m_s > 0) || !(bin.max_speed_m_s > bin.min_speed_m_s))
      r.fail(at, "expected 0 < min_speed_mm_s < max_speed_mm_s");
    bin.mean_speed_m_s = r.number_or_nan(b, "mean_speed_mm_s", at) / kMmPerM;
    bin.rows = r.count(b, "rows", at);
    bin.lsd_db = r.number_or_nan(b, "lsd_db", at);
    bin.measured_weighted_mean = r.number_or_nan(b, "measured_weighted_mean", at);
    bin.simulated_weighted_mean = r.number_or_nan(b, "simulated_weighted_mean", at);
    bin.weighted_mean_log10_difference = r.number_or_nan(b, "weighted_mean_log10_difference", at);
    c.bins.push_back(bin);
  }

  const json& overall = jf::as_object(jf::member(root, "overall", file, ""), file, "overall");
  c.bins_with_rows = r.count(overall, "bins_with_rows", "overall");
  c.rows = r.count(overall, "rows", "overall");
  c.rows_outside_speed_range = r.count(overall, "rows_outside_speed_range", "overall");
  c.mean_lsd_db = r.number_or_nan(overall, "mean_lsd_db", "overall");
  c.mean_weighted_mean_log10_difference =
      r.number_or_nan(overall, "mean_weighted_mean_log10_difference", "overall");

  const json& capture = jf::as_object(jf::member(root, "capture", file, ""), file, "capture");
  c.rows_analysed = r.count(capture, "rows_analysed", "capture");
  c.rows_without_speed = r.count(capture, "rows_without_speed", "capture");
  c.blocks_dropped = r.count(capture, "blocks_dropped", "capture");

  // Files written before the actuator was recorded have no such member.
  if (const auto a = root.find("actuator"); a != root.end() && !a->is_null()) {
    jf::as_object(*a, file, "actuator");
    ComparisonActuator actuator;
    actuator.contacts = r.count(*a, "contacts", "actuator");
    actuator.follow_mean_s = r.number(*a, "follow_mean_ms", "actuator") / 1e3;
    actuator.follow_max_s = r.number(*a, "follow_max_ms", "actuator") / 1e3;
    actuator.period_s = r.number(*a, "period_ms", "actuator") / 1e3;
    c.actuator = actuator;
  }
  return c;
}

}  // namespace nibrig::model::io
