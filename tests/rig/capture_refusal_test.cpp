// A capture refused before it recorded anything leaves nothing behind (no <out>.partial that the
// next capture to the same -o would trip over); one that fails after recording keeps what it has.
// The rig here is a fault injected on purpose: a rig that refuses to start, or fails at a read.
#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

#include "model/io/rig_session.hpp"
#include "rig/capture.hpp"
#include "rig/rig.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::rig {
namespace {

class FaultyRig : public Rig {
 public:
  FaultyRig(bool refuse_start, int reads_before_failing)
      : refuse_start_(refuse_start), reads_left_(reads_before_failing) {
    description_.kind = "simulated";
    description_.name = "a rig that fails on purpose";
    description_.tool = "vero2";
    description_.surface = "office";
    description_.max_speed_m_s = 0.4;
  }
  const RigDescription& description() const override { return description_; }
  void start(const SpeedProfile&) override {
    if (refuse_start_) throw std::runtime_error("the motor refused to start");
  }
  bool read(RigData& into, std::chrono::milliseconds) override {
    if (reads_left_-- <= 0) throw std::runtime_error("the rig stopped answering");
    SensorFrame frame{};
    into.frames.assign(10, frame);
    into.acceleration.assign(480, 0.5f);
    return true;
  }
  void stop() override {}
  RigHealth health() const override { return {}; }

 private:
  RigDescription description_;
  bool refuse_start_;
  int reads_left_;
};

TEST(CaptureRefusal, NothingRecordedLeavesNothingAndSomethingRecordedIsKept) {
  struct Case {
    const char* what;
    bool refuse_start;
    int good_reads;
    bool partial_kept;
  };
  const Case cases[] = {
      {"refused at start", true, 0, false},
      {"failed at the first read", false, 0, false},
      {"failed after recording", false, 3, true},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    const auto dir = nibrig::test::scratch_dir("capture_refusal");
    FaultyRig rig(c.refuse_start, c.good_reads);
    CaptureOptions options;
    options.folder = dir / "session";
    EXPECT_THROW(capture_session(rig, SpeedProfile("hold", {{0, 0.05}, {10.0, 0.05}}), options),
                 std::runtime_error);
    EXPECT_FALSE(std::filesystem::exists(dir / "session"));
    EXPECT_EQ(std::filesystem::exists(model::io::partial_folder_of(dir / "session")),
              c.partial_kept);
    if (c.partial_kept) {
      const auto kept = model::io::read_rig_session(model::io::partial_folder_of(dir / "session"));
      EXPECT_EQ(kept.acceleration.size(), 3u * 480u);
    }
  }
}

}  // namespace
}  // namespace nibrig::rig
