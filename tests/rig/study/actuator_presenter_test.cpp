// The experiment runner's actuator mode on a real JACK server: a participant asks for the
// reference, A and B in an order of their own, and an independent JACK client hears exactly that
// order; the study's log records it too. The three stimuli are one tool at three levels 12 dB
// apart, so that a window's level says which one sounds.
#include "rig/study/actuator_presenter.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "model/study/study_results.hpp"
#include "tests/model/study/study_test_support.hpp"
#include "tests/playback/jack_recorder.hpp"
#include "tests/playback/jack_stream_settings.hpp"
#include "tests/rig/bundled_sound.hpp"
#include "tests/support/jack_server.hpp"
#include "tests/support/test_paths.hpp"

namespace nibrig::rig {
namespace {

using namespace std::chrono_literals;
namespace study = model::study;

model::design::ToolSound louder(model::design::ToolSound s, double factor) {
  for (auto& row : s.spectrum.amplitude_m_s2)
    for (double& a : row) a *= factor;
  s.name += " x" + std::to_string(static_cast<int>(factor));
  return s;
}

// Plays the script's roles, each for `hold`, then calls `answering` and answers left.
class ScriptedParticipant final : public study::Respondent {
 public:
  ScriptedParticipant(std::string script, std::chrono::milliseconds hold,
                      std::function<void()> answering)
      : script_(std::move(script)), hold_(hold), answering_(std::move(answering)) {}
  bool agree(const study::StudyTexts&) override { return true; }
  study::Answer answer(const study::TrialPrompt&,
                       const std::function<void(study::Role)>& play) override {
    for (char c : script_) {
      play(static_cast<study::Role>(c));
      std::this_thread::sleep_for(hold_);
    }
    answering_();
    return {model::space::Choice::left, std::nullopt};
  }
  void rest(std::size_t, std::size_t) override {}

 private:
  std::string script_;
  std::chrono::milliseconds hold_;
  std::function<void()> answering_;
};

// The roles heard in a recording: 20 ms windows classified by level against the quietest sounding
// level (the reference, ×1), runs shorter than 100 ms (crossfades, a stroke's start) left out, and
// repeats merged.
std::string roles_heard(const std::vector<float>& samples, double rate) {
  const auto window = static_cast<std::size_t>(0.02 * rate);
  std::vector<double> rms;
  for (std::size_t at = 0; at + window <= samples.size(); at += window) {
    double sum = 0.0;
    for (std::size_t i = at; i < at + window; ++i) sum += double(samples[i]) * samples[i];
    rms.push_back(std::sqrt(sum / static_cast<double>(window)));
  }
  std::vector<double> sounding;
  for (double r : rms)
    if (r > 1e-4) sounding.push_back(r);
  if (sounding.empty()) return {};
  std::sort(sounding.begin(), sounding.end());
  const double quiet = sounding[sounding.size() / 20];  // 5th percentile: the ×1 level
  std::string heard;
  char current = 0;
  std::size_t run = 0;
  for (double r : rms) {
    char role = 0;
    if (r > 1e-4) {
      const double steps = std::log(r / quiet) / std::log(4.0);  // 12 dB a step
      role = steps < 0.5 ? 'R' : steps < 1.5 ? 'A' : 'B';
    }
    run = role == current ? run + 1 : 1;
    current = role;
    if (run == 5 && role != 0 && (heard.empty() || heard.back() != role)) heard.push_back(role);
  }
  return heard;
}

TEST(StudyActuatorJack, TheCaptureHearsTheStimuliInTheOrderTheParticipantAskedFor) {
  nibrig::testing::JackServer server;
  playback::LiveAudition audition(rt::EngineSettings{});
  audition.open(playback::testing::jack_settings("study"));
  const auto& cryon = testing::bundled_sound("cryon", "note");
  std::vector<model::design::ToolSound> sounds{cryon, louder(cryon, 4.0), louder(cryon, 16.0)};
  ActuatorPresenter presenter(audition, sounds,
                              [] { return std::make_unique<rt::ConstantStroke>(0.1); });

  study::StudyDefinition d = study::test::definition_of(3, study::PlanKind::file);
  d.practice = 0;
  d.listed_trials = {{0, 1, 2, 1}};
  const auto dir = nibrig::test::scratch_dir("study_actuator_jack");
  const auto folder = study::test::make_study(dir, d);
  study::StudySettings settings;
  settings.study = folder;
  settings.participant = "P01";

  const std::string script = "RBARAB";
  const auto hold = 400ms;
  playback::testing::JackRecorder ear("ear", 1, 48000 * 4);
  ASSERT_TRUE(ear.connect("study:outport 0", 0));
  ear.start();
  // The recording is cut where the participant answered: after that the stimulus stops and its
  // modes ring down through the lower levels, which is not a stimulus being asked for.
  jack_nframes_t answered_at = 0;
  ScriptedParticipant participant(script, hold,
                                  [&] { answered_at = jack_frame_time(ear.client()); });
  ASSERT_TRUE(study::run_study(settings, presenter, participant).complete);
  ASSERT_TRUE(ear.wait_full(20s));
  std::vector<float> asked = ear.samples(0);
  for (const auto& c : ear.cycles())
    if (answered_at >= c.time && answered_at - c.time < c.frames) asked.resize(c.start + (answered_at - c.time));
  ASSERT_LT(asked.size(), ear.samples(0).size()) << "the answer fell inside the recording";
  const std::string heard = roles_heard(asked, 48000.0);
  EXPECT_EQ(heard, script);
  const auto logged = study::read_study(folder).participants.at(0).responses.at(0);
  EXPECT_EQ(logged.plays, script);
  EXPECT_EQ(audition.output_stats()->losses, 0u);
}

}  // namespace
}  // namespace nibrig::rig
