// Finds the constant-speed blocks of a turntable vibration recording from the signal itself: where
// the tip starts moving, and the 2 s grid of speed steps of every sweep. The recordings of the
// paper do not store speeds or step times; the paper's code used hand-picked start rows instead.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace nibrig::model::measure {

// linspace(0.017, 0.250, 6) m/s: the paper's 17-250 mm/s range (Sec. 3, the pilot study's 5th-95th
// speed percentiles) spread evenly over the six kept blocks. An ASSUMPTION: the recordings do not
// store the turntable speeds and the paper does not list the six set points; only the range and the
// fact that the speed rises from block to block (the vibration level does) are known.
std::vector<double> default_step_speeds_m_s();

// The rig's protocol. Each sweep is blocks_per_sweep blocks of block_s seconds; the first
// skipped_blocks_per_sweep blocks are not analysed (in the recordings the first is the turntable at
// rest or starting), the others hold one speed each, rising. In every kept block a window of
// window_length_s starting window_offset_s into the block is analysed (the paper's code: 1500 of
// 2000 samples from 250). Continuous recordings have a pause of about 4 s between sweeps (sweeps 16
// s apart), files cut into 14 s pieces about 2 s; the search below does not assume either.
struct StepProtocol {
  double block_s = 2.0;
  std::size_t blocks_per_sweep = 7;
  std::size_t skipped_blocks_per_sweep = 1;
  std::size_t sweeps = 3;  // expected; as many complete sweeps as found are used (at least 1)
  double window_offset_s = 0.25;
  double window_length_s = 1.5;
  std::vector<double> speeds_m_s = default_step_speeds_m_s();  // one per kept block, in block order
  // The level envelope that the steps are found in: log power in [envelope_low_hz,
  // envelope_high_hz] of Hann frames of envelope_frame_s every envelope_hop_s. 20-150 Hz is where
  // moving and resting differ most on every surface of the paper's data (on glass the broadband
  // level barely changes).
  double envelope_low_hz = 20.0;
  double envelope_high_hz = 150.0;
  double envelope_frame_s = 0.25;
  double envelope_hop_s = 0.01;
};

struct SpeedStep {
  std::size_t begin = 0;  // analysis window [begin, end), samples
  std::size_t end = 0;
  std::size_t sweep = 0;  // 0-based, in time order
  std::size_t block = 0;  // index in the sweep's block grid: skipped blocks are 0..skipped-1
  double speed_m_s = 0.0;
  double rms_m_s2 = 0.0;  // RMS of the mean-removed window
};

struct StepSegmentation {
  // First sample of the first kept block of the first sweep: where the tip starts moving over the
  // surface (before it the signal is the quiet level of the resting rig).
  std::size_t contact_begin = 0;
  std::vector<SpeedStep> steps;  // sweep by sweep, block by block
  std::vector<std::string> warnings;
};

// The method. (1) Envelope e: log band power of short frames (see StepProtocol). (2) Robust levels:
// the resting level is the 10th and the moving level the 75th percentile of e smoothed over 1/8
// block. (3) Edge candidates: a step statistic (mean of e over the next half block minus the
// previous half block) has strong maxima where motion starts and strong minima where it stops;
// every start proposes a sweep whose first kept block begins there, every stop one whose last kept
// block ends there. (4) Each proposal is refined by fitting a piecewise-constant model to e — one
// level per kept block plus one resting level shared by the block before and the block after — over
// shifts of ±1/4 block; the sweep must be louder than rest in every kept block. (5) Non-overlapping
// sweeps are taken best first (mean kept level above the resting level). (6) Each sweep's grid is
// placed to the sample by maximum likelihood of a piecewise-constant noise power in the
// (high-passed) signal, within 1/8 block. Steps are then placed on the grid with the protocol's
// window. On synthetic steps the block edges come out within 10 samples; on the paper's data they
// agree with its hand-picked rows to within 81 samples (see the tests). Throws
// std::invalid_argument on an inconsistent protocol or a non-positive rate, std::runtime_error when
// the signal is too short or holds no sweep.
StepSegmentation segment_speed_steps(std::span<const double> acceleration, double sample_rate_hz,
                                     const StepProtocol& protocol);

// The steps of a recording whose speed profile is known (a rig capture stores what the motor was
// asked to do: breakpoints joined by straight lines, a step being two points at one time). Every
// hold of one positive speed at least window_offset_s + window_length_s long gives a step whose
// window starts window_offset_s into the hold (the motor has settled by then) and lasts
// window_length_s; `sweep` counts the holds of the same speed, `block` numbers the holds. Windows
// that do not fit in the `signal_length` samples recorded (a capture cut short) are left out. No
// step is an empty result, not an error. Throws std::invalid_argument for arrays of different
// lengths or a non-positive rate.
StepSegmentation steps_from_profile(std::span<const double> time_s, std::span<const double> speed_m_s,
                                    double sample_rate_hz, std::size_t signal_length,
                                    const StepProtocol& protocol);

}  // namespace nibrig::model::measure
