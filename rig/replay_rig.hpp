// A recording played back as if the rig were running: a captured session, or one of the paper's
// turntable recordings with the speed steps found in its signal (model/measure/step_segmentation).
// Everything downstream — capture, measurement, live comparison — cannot tell it from a live rig,
// which is what makes a recorded afternoon at the turntable reusable, and what tests the chain
// against the catalog: a paper recording replayed and measured gives the catalog's spectrum. The
// paper recorded vibration and friction in separate runs; a vibration recording replayed with its
// friction recording plays that run's forces beside it, so the session measures μ too.
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "rig/pacer.hpp"
#include "rig/rig.hpp"

namespace nibrig::rig {

class ReplayRig final : public Rig {
 public:
  // `source`: a session folder (finished or .partial) or a paper vibration recording
  // (arm_*.csv[.gz]). Throws model::io::FormatError naming the file for a bad recording and
  // std::invalid_argument for a session without speed or a recording whose steps are not found.
  // `friction`: a paper friction recording whose forces the frames carry from the start (at rest
  // after it ends); only beside a paper vibration recording (a session has its own forces).
  ReplayRig(const std::filesystem::path& source, double speedup,
            const std::filesystem::path& friction = {});

  const RigDescription& description() const override { return description_; }
  // What the recording's motor was asked to do (its steps, or the session's stored profile; for a
  // session without one, its measured speed as it was).
  const SpeedProfile& recorded_profile() const { return *profile_; }
  const SpeedProfile* own_profile() const override { return &*profile_; }
  // Plays the recording from its start for `profile`'s length (at most the recording's): a replay
  // cannot change what was recorded, so only the length of the profile counts.
  void start(const SpeedProfile& profile) override;
  bool read(RigData& into, std::chrono::milliseconds wait) override;
  void stop() override;
  RigHealth health() const override { return health_; }

 private:
  RigDescription description_;
  std::optional<SpeedProfile> profile_;
  std::vector<SensorFrame> frames_;
  std::vector<float> acceleration_;
  Pacer pacer_;
  RigHealth health_;
  std::uint64_t frames_made_ = 0, frames_total_ = 0, samples_made_ = 0;
  bool started_ = false, stopped_ = false;
};

}  // namespace nibrig::rig
