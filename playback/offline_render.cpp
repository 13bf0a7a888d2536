#include "playback/offline_render.hpp"

#include <sndfile.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/io/atomic_file.hpp"

namespace nibrig::playback {
namespace {

struct SndfileCloser {
  void operator()(SNDFILE* f) const { sf_close(f); }
};

}  // namespace

OfflineRenderResult render_to_wav(rt::BlockRenderer& renderer, const std::filesystem::path& wav,
                                  const OfflineRenderSettings& settings) {
  if (!(settings.sample_rate_hz > 0) || settings.block_frames == 0 || !(settings.seconds > 0))
    throw std::invalid_argument("an offline render needs a positive rate, block and duration");
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
