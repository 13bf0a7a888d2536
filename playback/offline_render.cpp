#include "playback/offline_render.hpp"

#include <sndfile.h>

#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/io/atomic_file.hpp"

namespace nibrig::playback {
namespace {

struct SndfileCloser {
  void operator()(SNDFILE* f) const { sf_close(f); }
};

void refuse_render_value(const std::string& who, double value, const char* unit, const std::string& expected) {
  std::ostringstream message;
  message << who << ": " << value << " " << unit << ": expected " << expected;
  throw std::invalid_argument(message.str());
}

bool render_within(double value, double low, double high) {
  return std::isfinite(value) && value >= low && value <= high;
}

std::string render_range(double low, double high) {
  std::ostringstream s;
  s << low << " to " << high;
  return s.str();
}

}  // namespace

void check_render_rate(double rate_hz, const std::string& who) {
  if (!render_within(rate_hz, kLowestRenderRateHz, kHighestRenderRateHz))
    refuse_render_value(who, rate_hz, "Hz",
                        "a sample rate in Hz, " + render_range(kLowestRenderRateHz, kHighestRenderRateHz));
}

void check_render_block(std::size_t frames, const std::string& who) {
  if (frames < 1 || frames > kLargestRenderBlock)
    refuse_render_value(who, static_cast<double>(frames), "frames",
                        "a block size in frames, 1 to " + std::to_string(kLargestRenderBlock));
}

void check_render_seconds(double seconds, const std::string& who) {
  if (!render_within(seconds, kShortestRenderSeconds, kLongestRenderSeconds))
    refuse_render_value(who, seconds, "s",
                        "a length in seconds, " + render_range(kShortestRenderSeconds, kLongestRenderSeconds));
}

void check_stroke_request(const rt::StrokeRequest& request) {
  const auto off_or_within = [](double v, double low, double high) { return v == 0.0 || render_within(v, low, high); };
  if (request.speed_m_s && !off_or_within(*request.speed_m_s, kSlowestStrokeM_s, kFastestStrokeM_s))
    refuse_render_value("speed", *request.speed_m_s, "m/s",
                        "a speed in m/s, 0 or " + render_range(kSlowestStrokeM_s, kFastestStrokeM_s));
  if (request.force_n && !off_or_within(*request.force_n, kLightestStrokeN, kHeaviestStrokeN))
    refuse_render_value("force", *request.force_n, "N",
                        "a normal force in N, 0 or " + render_range(kLightestStrokeN, kHeaviestStrokeN));
}

OfflineRenderResult render_to_wav(rt::BlockRenderer& renderer, const std::filesystem::path& wav,
                                  const OfflineRenderSettings& settings) {
  check_render_rate(settings.sample_rate_hz, "render rate");
  check_render_block(settings.block_frames, "render block");
  check_render_seconds(settings.seconds, "render length");
  const model::io::OutputTarget target = model::io::output_target(wav);
  const std::filesystem::path partial = model::io::temporary_beside(target);
  // Whatever stops the render (a full disk, a renderer that throws, a failed rename) removes the
  // half file: only a finished render is left behind, under its own name.
  struct RemoveUnlessDone {
    const std::filesystem::path& path;
    bool done = false;
    ~RemoveUnlessDone() {
      std::error_code ignored;  // nothing more to do if it cannot be removed: the throw names it
      if (!done) std::filesystem::remove(path, ignored);
    }
  } cleanup{partial};
  SF_INFO format{};
  format.samplerate = static_cast<int>(std::lround(settings.sample_rate_hz));
  format.channels = 1;
  format.format = SF_FORMAT_WAV | SF_FORMAT_FLOAT;
  std::unique_ptr<SNDFILE, SndfileCloser> file(sf_open(partial.c_str(), SFM_WRITE, &format));
  if (!file)
    throw std::runtime_error("cannot write " + partial.string() + " (" + sf_strerror(nullptr) + ")");
  sf_command(file.get(), SFC_SET_UPDATE_HEADER_AUTO, nullptr, SF_TRUE);

  OfflineRenderResult result;
  result.frames = static_cast<std::size_t>(std::llround(settings.seconds * settings.sample_rate_hz));
  std::vector<float> block(settings.block_frames);
  double sum_squares = 0;
  for (std::size_t done = 0; done < result.frames;) {
    const std::size_t n = std::min(block.size(), result.frames - done);
    renderer.render(block.data(), n);
    for (std::size_t i = 0; i < n; ++i) {
      result.peak = std::max(result.peak, static_cast<double>(std::abs(block[i])));
      sum_squares += static_cast<double>(block[i]) * block[i];
    }
    if (sf_write_float(file.get(), block.data(), static_cast<sf_count_t>(n)) != static_cast<sf_count_t>(n))
      throw std::runtime_error("cannot write " + partial.string() + " (" + sf_strerror(file.get()) + ")");
    done += n;
  }
  result.rms = std::sqrt(sum_squares / static_cast<double>(result.frames));
  if (sf_close(file.release()) != 0)
    throw std::runtime_error("cannot finish " + partial.string());
  cleanup.done = true;  // commit_output removes it whatever happens
  model::io::commit_output(partial, target);
  return result;
}

}  // namespace nibrig::playback
