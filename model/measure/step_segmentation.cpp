#include "model/measure/step_segmentation.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include "model/measure/order_statistics.hpp"
#include "model/measure/spectrum_analyzer.hpp"
#include "model/numeric/real_fft.hpp"

namespace nibrig::model::measure {

std::vector<double> default_step_speeds_m_s() {
  std::vector<double> speeds(6);
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    speeds[i] = 0.017 + (0.250 - 0.017) * static_cast<double>(i) / 5.0;
  }
  return speeds;
}

namespace {

// The envelope must rise at least this much (natural log of amplitude) from resting to moving for
// any step to be found: the paper's recordings have 0.9-2.5.
constexpr double kMinContrast = 0.3;
// Edge candidates need a step statistic of this fraction of the contrast.
constexpr double kStepEdgeFraction = 0.4;
// A kept block must be louder than rest by this fraction of the contrast.
constexpr double kMovingFraction = 0.15;

// O(1) mean and residual sum of squares of any range of a sequence.
class PrefixSums {
 public:
  explicit PrefixSums(const std::vector<double>& v)
      : s1_(v.size() + 1, 0.0), s2_(v.size() + 1, 0.0) {
    for (std::size_t i = 0; i < v.size(); ++i) {
      s1_[i + 1] = s1_[i] + v[i];
      s2_[i + 1] = s2_[i] + v[i] * v[i];
    }
  }
  std::ptrdiff_t size() const { return static_cast<std::ptrdiff_t>(s1_.size()) - 1; }
  // Sums over [a, b) clipped to the sequence.
  void add(std::ptrdiff_t a, std::ptrdiff_t b, double& sum, double& sum_sq, double& count) const {
    a = std::clamp<std::ptrdiff_t>(a, 0, size());
    b = std::clamp<std::ptrdiff_t>(b, 0, size());
    if (b <= a) return;
    sum += s1_[static_cast<std::size_t>(b)] - s1_[static_cast<std::size_t>(a)];
    sum_sq += s2_[static_cast<std::size_t>(b)] - s2_[static_cast<std::size_t>(a)];
    count += static_cast<double>(b - a);
  }
  double sse(std::ptrdiff_t a, std::ptrdiff_t b) const {
    double s = 0, ss = 0, m = 0;
    add(a, b, s, ss, m);
    return m > 0 ? ss - s * s / m : 0.0;
  }
  double mean(std::ptrdiff_t a, std::ptrdiff_t b, double fallback) const {
    double s = 0, ss = 0, m = 0;
    add(a, b, s, ss, m);
    return m > 0 ? s / m : fallback;
  }

 private:
  std::vector<double> s1_, s2_;
};

std::vector<double> moving_mean(const std::vector<double>& v, std::ptrdiff_t width) {
  const PrefixSums sums(v);
  std::vector<double> out(v.size());
  for (std::ptrdiff_t i = 0; i < sums.size(); ++i) {
    out[static_cast<std::size_t>(i)] = sums.mean(i - width / 2, i - width / 2 + width, v[0]);
  }
  return out;
}

// Indices of the strongest values of `sig` at or above `threshold`, at least `radius` apart.
std::vector<std::ptrdiff_t> strongest(const std::vector<double>& sig, double threshold,
                                      std::ptrdiff_t radius) {
  std::vector<std::ptrdiff_t> order(sig.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](auto a, auto b) {
    return sig[static_cast<std::size_t>(a)] > sig[static_cast<std::size_t>(b)];
  });
  std::vector<std::ptrdiff_t> taken;
  for (auto i : order) {
    if (sig[static_cast<std::size_t>(i)] < threshold) break;
    const bool far =
        std::all_of(taken.begin(), taken.end(), [&](auto t) { return std::abs(i - t) > radius; });
    if (far) taken.push_back(i);
  }
  return taken;
}

struct Envelope {
  std::vector<double> log_level;  // 0.5 log(band power): log amplitude, one per frame
  std::size_t frame = 0;          // samples
  std::size_t hop = 0;            // samples
};

// Sample at which the boundary before frame t lies: midway between the centres of frames t-1 and t
// (a periodic Hann frame of L samples starting at s is centred on s + L/2).
std::size_t frame_to_sample(const Envelope& env, std::ptrdiff_t t) {
  const auto hop = static_cast<double>(env.hop);
  return static_cast<std::size_t>(
      std::lround(static_cast<double>(t) * hop + (static_cast<double>(env.frame) - hop) / 2.0));
}

Envelope band_envelope(std::span<const double> x, double fs, const StepProtocol& p) {
  Envelope env;
  env.frame = static_cast<std::size_t>(std::lround(p.envelope_frame_s * fs));
  env.hop = std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(p.envelope_hop_s * fs)));
  if (env.frame < 8)
    throw std::invalid_argument("step segmentation: envelope frame under 8 samples");
  const std::size_t frames = (x.size() - env.frame) / env.hop + 1;
  SpectrumAnalyzer analyzer(env.frame, Window::hann);
  std::vector<double> psd(analyzer.bins());
  const double df = fs / static_cast<double>(env.frame);
  std::vector<double> power(frames);
  for (std::size_t f = 0; f < frames; ++f) {
    analyzer.power_spectral_density(x.subspan(f * env.hop, env.frame), fs, psd);
    double sum = 0.0;
    for (std::size_t k = 0; k < psd.size(); ++k) {
      const double freq = static_cast<double>(k) * df;
      if (freq >= p.envelope_low_hz && freq <= p.envelope_high_hz) sum += psd[k] * df;
    }
    power[f] = sum;
  }
  const double peak = *std::max_element(power.begin(), power.end());
  if (!(peak > 0.0) || !std::isfinite(peak)) {
    throw std::runtime_error("step segmentation: the signal has no finite energy in " +
                             std::to_string(p.envelope_low_hz) + "-" +
                             std::to_string(p.envelope_high_hz) + " Hz");
  }
  // A floor far below any real level keeps log() finite on digital silence.
  const double floor = peak * 1e-12;
  env.log_level.resize(frames);
  for (std::size_t f = 0; f < frames; ++f) env.log_level[f] = 0.5 * std::log(power[f] + floor);
  return env;
}

// Instantaneous power of the signal filtered to [low, high] Hz by masking its spectrum (zero
// phase).
std::vector<double> band_power_per_sample(std::span<const double> x, double fs, double low,
                                          double high) {
  const std::size_t n = x.size();
  numeric::RealFft fft(n, numeric::RealFft::Plans::forward_and_backward);
  const std::span<double> real = fft.real();
  std::copy(x.begin(), x.end(), real.begin());
  fft.forward();
  const std::span<std::complex<double>> spec = fft.spectrum();
  for (std::size_t k = 0; k < spec.size(); ++k) {
    const double f = static_cast<double>(k) * fs / static_cast<double>(n);
    if (f < low || f > high) spec[k] = 0.0;
  }
  fft.backward();
  std::vector<double> power(n);
  const double scale = 1.0 / static_cast<double>(n);  // FFTW's round trip multiplies by n
  for (std::size_t i = 0; i < n; ++i) power[i] = std::pow(real[i] * scale, 2);
  return power;
}

void validate(const StepProtocol& p, double fs) {
  auto fail = [](const std::string& what) {
    throw std::invalid_argument("step protocol: " + what);
  };
  if (!(fs > 0.0) || !std::isfinite(fs)) fail("sample rate must be positive and finite");
  if (!(p.block_s > 0.0)) fail("block_s must be positive");
  if (p.blocks_per_sweep <= p.skipped_blocks_per_sweep) fail("no kept block per sweep");
  if (p.sweeps == 0) fail("sweeps must be at least 1");
  if (!(p.window_offset_s >= 0.0) || !(p.window_length_s > 0.0) ||
      p.window_offset_s + p.window_length_s > p.block_s * (1.0 + 1e-9)) {
    fail("the analysis window must lie inside a block");
  }
  const std::size_t kept = p.blocks_per_sweep - p.skipped_blocks_per_sweep;
  if (p.speeds_m_s.size() != kept) {
    fail(std::to_string(p.speeds_m_s.size()) + " speeds for " + std::to_string(kept) +
         " kept blocks per sweep");
  }
  if (!(p.envelope_low_hz >= 0.0) || !(p.envelope_high_hz > p.envelope_low_hz) ||
      p.envelope_high_hz > fs / 2.0) {
    fail("envelope band must satisfy 0 <= low < high <= fs/2");
  }
  if (!(p.envelope_frame_s > 0.0) || !(p.envelope_hop_s > 0.0)) {
    fail("envelope frame and hop must be positive");
  }
}

struct Sweep {
  std::ptrdiff_t start_frame = 0;  // first kept block, on the envelope's frame grid
  double score = 0.0;              // mean kept level above the resting level (log amplitude)
  std::size_t start_sample = 0;    // first kept block, refined to the sample
};

// Steps (1)-(5) of the header: sweeps found on the frame grid of the log envelope, best first.
std::vector<Sweep> find_sweeps_on_frames(const Envelope& env, std::size_t samples,
                                         std::size_t block, std::ptrdiff_t kept,
                                         std::size_t blocks_per_sweep) {
  const std::vector<double>& e = env.log_level;
  const auto frames = static_cast<std::ptrdiff_t>(e.size());
  const auto bf = static_cast<std::ptrdiff_t>(
      std::lround(static_cast<double>(block) / static_cast<double>(env.hop)));
  if (bf < 8) throw std::invalid_argument("step protocol: envelope hop too coarse for the block");

  const std::vector<double> smooth = moving_mean(e, std::max<std::ptrdiff_t>(1, bf / 8));
  const double rest = quantile(smooth, 0.10);
  const double moving = quantile(smooth, 0.75);
  const double contrast = moving - rest;
  if (contrast < kMinContrast) {
    throw std::runtime_error(
        "step segmentation: the vibration level hardly changes (moving minus "
        "resting " +
        std::to_string(contrast) + " < " + std::to_string(kMinContrast) +
        " in log amplitude): no speed steps");
  }

  const PrefixSums sums(e);
  const std::ptrdiff_t half = bf / 2;
  std::vector<double> rise(e.size(), 0.0);
  for (std::ptrdiff_t i = half; i + half <= frames; ++i) {
    rise[static_cast<std::size_t>(i)] = sums.mean(i, i + half, 0.0) - sums.mean(i - half, i, 0.0);
  }
  std::vector<double> fall(rise.size());
  std::transform(rise.begin(), rise.end(), fall.begin(), [](double v) { return -v; });
  const double edge = kStepEdgeFraction * contrast;

  // Latest start frame whose kept blocks (and so their analysis windows) still fit in the signal.
  std::ptrdiff_t last_start = -1;
  for (std::ptrdiff_t t = frames - 1; t >= 0; --t) {
    if (frame_to_sample(env, t) + static_cast<std::size_t>(kept) * block <= samples) {
      last_start = t;
      break;
    }
  }
  std::vector<std::ptrdiff_t> proposals;
  for (auto u : strongest(rise, edge, bf)) proposals.push_back(u);
  for (auto s : strongest(fall, edge, bf)) proposals.push_back(s - kept * bf);
  std::erase_if(proposals, [&](auto t) { return t < 0 || t > last_start; });
  std::sort(proposals.begin(), proposals.end());

  // Residual sum of squares of the sweep model with its first kept block at frame t: one level per
  // kept block, one shared by the block before and the block after.
  auto cost = [&](std::ptrdiff_t t) {
    double s = 0, ss = 0, m = 0;
    sums.add(t - bf, t, s, ss, m);
    sums.add(t + kept * bf, t + (kept + 1) * bf, s, ss, m);
    double total = m > 0 ? ss - s * s / m : 0.0;
    for (std::ptrdiff_t k = 0; k < kept; ++k) total += sums.sse(t + k * bf, t + (k + 1) * bf);
    return total;
  };

  std::vector<Sweep> found;
  for (std::size_t i = 0; i < proposals.size();) {
    // Proposals within half a block of each other are one sweep seen from both of its ends.
    std::size_t j = i;
    while (j + 1 < proposals.size() && proposals[j + 1] - proposals[j] <= half) ++j;
    const std::ptrdiff_t lo = std::max<std::ptrdiff_t>(0, proposals[i] - bf / 4);
    const std::ptrdiff_t hi = std::min(last_start, proposals[j] + bf / 4);
    i = j + 1;
    std::ptrdiff_t best = lo;
    double best_cost = std::numeric_limits<double>::infinity();
    for (std::ptrdiff_t t = lo; t <= hi; ++t) {
      const double c = cost(t);
      if (c < best_cost) {
        best_cost = c;
        best = t;
      }
    }
    double level_sum = 0.0;
    bool all_moving = true;
    for (std::ptrdiff_t k = 0; k < kept; ++k) {
      const double level = sums.mean(best + k * bf, best + (k + 1) * bf, rest);
      level_sum += level;
      all_moving = all_moving && level > rest + kMovingFraction * contrast;
    }
    double s = 0, ss = 0, m = 0;
    sums.add(best - bf, best, s, ss, m);
    sums.add(best + kept * bf, best + (kept + 1) * bf, s, ss, m);
    const double resting = m > 0 ? s / m : rest;
    if (all_moving) found.push_back({best, level_sum / static_cast<double>(kept) - resting, 0});
  }

  std::sort(found.begin(), found.end(),
            [](const Sweep& a, const Sweep& b) { return a.score > b.score; });
  const auto spacing = static_cast<std::ptrdiff_t>(blocks_per_sweep) * bf - bf / 4;
  std::vector<Sweep> chosen;
  for (const Sweep& s : found) {
    const bool apart = std::all_of(chosen.begin(), chosen.end(), [&](const Sweep& c) {
      return std::abs(c.start_frame - s.start_frame) >= spacing;
    });
    if (apart) chosen.push_back(s);
  }
  return chosen;
}

// Step (6): the frame grid finds sweeps robustly (levels span decades) but a log-level edge seen
// through a 250 ms frame lands tens of ms towards the quiet side. Here the change points are placed
// by maximum likelihood in the signal itself, modelled as Gaussian noise of piecewise-constant
// power (cost Σ_segments n log(mean power)), within 1/8 block of the frame estimate. Only the
// resting offset and drift below `low_hz` are filtered out: a band-pass would smear each edge over
// its impulse response, and the likelihood, which weighs a loud sample in a quiet segment far more
// than the reverse, would pull the edges towards the quiet side again.
void refine_to_samples(std::span<const double> x, double fs, double low_hz, const Envelope& env,
                       std::size_t block, std::ptrdiff_t kept, std::vector<Sweep>& sweeps) {
  const std::vector<double> power = band_power_per_sample(x, fs, low_hz, fs);
  std::vector<double> prefix(power.size() + 1, 0.0);
  for (std::size_t i = 0; i < power.size(); ++i) prefix[i + 1] = prefix[i] + power[i];
  const double tiny = std::max(prefix.back() / static_cast<double>(power.size()), 1e-300) * 1e-12;
  const auto n = static_cast<std::ptrdiff_t>(x.size());
  const auto blk = static_cast<std::ptrdiff_t>(block);
  auto segment = [&](std::ptrdiff_t a, std::ptrdiff_t b, double& sum, double& count) {
    a = std::clamp<std::ptrdiff_t>(a, 0, n);
    b = std::clamp<std::ptrdiff_t>(b, 0, n);
    if (b <= a) return;
    sum += prefix[static_cast<std::size_t>(b)] - prefix[static_cast<std::size_t>(a)];
    count += static_cast<double>(b - a);
  };
  auto neg_log_likelihood = [&](std::ptrdiff_t t) {
    double total = 0.0;
    double sum = 0.0, count = 0.0;
    segment(t - blk, t, sum, count);
    segment(t + kept * blk, t + (kept + 1) * blk, sum, count);
    if (count > 0) total += count * std::log(sum / count + tiny);
    for (std::ptrdiff_t k = 0; k < kept; ++k) {
      sum = count = 0.0;
      segment(t + k * blk, t + (k + 1) * blk, sum, count);
      total += count * std::log(sum / count + tiny);
    }
    return total;
  };
  const std::ptrdiff_t reach = blk / 8;
  const std::ptrdiff_t latest = n - kept * blk;
  for (Sweep& sw : sweeps) {
    const auto guess = static_cast<std::ptrdiff_t>(frame_to_sample(env, sw.start_frame));
    std::ptrdiff_t best = guess;
    double best_cost = std::numeric_limits<double>::infinity();
    for (std::ptrdiff_t t = std::max<std::ptrdiff_t>(0, guess - reach);
         t <= std::min(latest, guess + reach); ++t) {
      const double c = neg_log_likelihood(t);
      if (c < best_cost) {
        best_cost = c;
        best = t;
      }
    }
    sw.start_sample = static_cast<std::size_t>(best);
  }
}

}  // namespace

StepSegmentation segment_speed_steps(std::span<const double> x, double fs, const StepProtocol& p) {
  validate(p, fs);
  const auto kept = static_cast<std::ptrdiff_t>(p.blocks_per_sweep - p.skipped_blocks_per_sweep);
  const auto block = static_cast<std::size_t>(std::lround(p.block_s * fs));
  const auto frame = static_cast<std::size_t>(std::lround(p.envelope_frame_s * fs));
  if (x.size() < frame || x.size() < static_cast<std::size_t>(kept + 1) * block) {
    throw std::runtime_error("too short for the step protocol: " + std::to_string(x.size()) +
                             " samples cannot hold one sweep of " + std::to_string(kept) +
                             " speed blocks of " + std::to_string(block) +
                             " samples (is the recording cut off?)");
  }
  const Envelope env = band_envelope(x, fs, p);
  std::vector<Sweep> chosen = find_sweeps_on_frames(env, x.size(), block, kept, p.blocks_per_sweep);
  if (chosen.empty()) {
    throw std::runtime_error("step segmentation: no sweep of " + std::to_string(kept) +
                             " moving blocks found");
  }

  StepSegmentation result;
  if (chosen.size() > p.sweeps) {
    result.warnings.push_back("found " + std::to_string(chosen.size()) + " sweeps, kept the " +
                              std::to_string(p.sweeps) + " clearest");
    chosen.resize(p.sweeps);
  } else if (chosen.size() < p.sweeps) {
    result.warnings.push_back("found " + std::to_string(chosen.size()) + " complete sweeps, " +
                              std::to_string(p.sweeps) + " expected");
  }
  std::sort(chosen.begin(), chosen.end(),
            [](const Sweep& a, const Sweep& b) { return a.start_frame < b.start_frame; });
  const auto bf = static_cast<std::ptrdiff_t>(block / env.hop);
  for (std::size_t j = 1; j + 1 < chosen.size(); ++j) {
    const auto before = chosen[j].start_frame - chosen[j - 1].start_frame;
    const auto after = chosen[j + 1].start_frame - chosen[j].start_frame;
    if (std::abs(before - after) > bf / 2) {
      result.warnings.push_back("sweeps are unevenly spaced around sweep " + std::to_string(j));
    }
  }
  refine_to_samples(x, fs, p.envelope_low_hz, env, block, kept, chosen);

  const auto offset = static_cast<std::size_t>(std::lround(p.window_offset_s * fs));
  // Rounding each to whole samples must not push the window past its block.
  const auto length = std::min(static_cast<std::size_t>(std::lround(p.window_length_s * fs)),
                               block - std::min(block, offset));
  for (std::size_t j = 0; j < chosen.size(); ++j) {
    const std::size_t first = chosen[j].start_sample;
    if (j == 0) result.contact_begin = first;
    for (std::ptrdiff_t k = 0; k < kept; ++k) {
      SpeedStep step;
      step.begin = first + static_cast<std::size_t>(k) * block + offset;
      step.end = step.begin + length;  // inside: refined starts leave room for all kept blocks
      step.sweep = j;
      step.block = p.skipped_blocks_per_sweep + static_cast<std::size_t>(k);
      step.speed_m_s = p.speeds_m_s[static_cast<std::size_t>(k)];
      const auto window = x.subspan(step.begin, step.end - step.begin);
      const double mean =
          std::accumulate(window.begin(), window.end(), 0.0) / static_cast<double>(window.size());
      double sq = 0.0;
      for (double v : window) sq += (v - mean) * (v - mean);
      step.rms_m_s2 = std::sqrt(sq / static_cast<double>(window.size()));
      result.steps.push_back(step);
    }
  }
  return result;
}

}  // namespace nibrig::model::measure

namespace nibrig::model::measure {

StepSegmentation steps_from_profile(std::span<const double> time_s, std::span<const double> speed_m_s,
                                    double sample_rate_hz, std::size_t signal_length,
                                    const StepProtocol& protocol) {
  if (time_s.size() != speed_m_s.size())
    throw std::invalid_argument("a speed profile needs one speed per time");
  if (!(sample_rate_hz > 0.0) || !std::isfinite(sample_rate_hz))
    throw std::invalid_argument("the sample rate must be positive");
  StepSegmentation result;
  const auto window = static_cast<std::size_t>(std::llround(protocol.window_length_s * sample_rate_hz));
  std::vector<double> seen;  // speeds so far, to count sweeps
  std::size_t block = 0;
  for (std::size_t i = 0; i + 1 < time_s.size(); ++i) {
    const double v = speed_m_s[i];
    if (!(v > 0.0) || speed_m_s[i + 1] != v) continue;
    if (time_s[i + 1] - time_s[i] < protocol.window_offset_s + protocol.window_length_s) continue;
    const auto begin =
        static_cast<std::size_t>(std::llround((time_s[i] + protocol.window_offset_s) * sample_rate_hz));
    const std::size_t this_block = block++;
    if (begin + window > signal_length) continue;
    SpeedStep step;
    step.begin = begin;
    step.end = begin + window;
    step.speed_m_s = v;
    step.block = this_block;
    step.sweep = static_cast<std::size_t>(std::count(seen.begin(), seen.end(), v));
    seen.push_back(v);
    if (result.steps.empty())
      result.contact_begin = static_cast<std::size_t>(std::llround(time_s[i] * sample_rate_hz));
    result.steps.push_back(step);
  }
  return result;
}

}  // namespace nibrig::model::measure
