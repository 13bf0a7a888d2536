#include "rig/pen/pen_contact.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include "model/design/tool_sound.hpp"
#include "playback/prepared_engine.hpp"
#include "rig/pen/pen_clock.hpp"
#include "rt/stroke_source.hpp"
#include "tests/rig/bundled_sound.hpp"
#include "tests/rig/pen/pen_speed_synthetic_stroke.hpp"

namespace nibrig::rig::pen {
namespace {

// What the callbacks said, in order.
struct PenContactLog {
  std::vector<PenContactSample> contacts;
  std::vector<std::string> events;  // "began 1", "ended 1 tip up"
  PenContactEvents events_to_log() {
    PenContactEvents e;
    e.contact = [this](const PenContactSample& c) {
      contacts.push_back(c);
      events.push_back("contact");
    };
    e.stroke_began = [this](std::uint64_t n) { events.push_back("began " + std::to_string(n)); };
    e.stroke_ended = [this](std::uint64_t n, PenStrokeEnd why) {
      events.push_back("ended " + std::to_string(n) + " " + pen_stroke_end_name(why));
    };
    return e;
  }
};

PenSample pen_contact_report(double t, double x, double pressure, bool tip_down,
                             bool in_proximity = true) {
  PenSample s;
  s.time_s = t;
  s.x_m = x;
  s.y_m = 0.03;
  s.pressure = pressure;
  s.tip_down = tip_down;
  s.in_proximity = in_proximity;
  return s;
}

TEST(PenContact, TipDownStartsAStrokeAndTipUpEndsItWithSpeedAndForceZero) {
  PenContactLog log;
  PenContact contact(default_pressure_curve(), log.events_to_log());
  contact.on_sample(pen_contact_report(1.000, 0.010, 0.0, false));  // hovering: nothing
  EXPECT_TRUE(log.events.empty());
  contact.on_sample(pen_contact_report(1.010, 0.010, 0.5, true));
  contact.on_sample(pen_contact_report(1.020, 0.011, 0.5, true));
  contact.on_sample(pen_contact_report(1.030, 0.012, 0.5, true));
  contact.on_sample(pen_contact_report(1.040, 0.012, 0.0, false));
  contact.on_sample(pen_contact_report(1.050, 0.013, 0.0, false));  // hovering again: nothing
  EXPECT_EQ(log.events, (std::vector<std::string>{"began 1", "contact", "contact", "contact",
                                                  "contact", "ended 1 tip up"}));
  ASSERT_EQ(log.contacts.size(), 4u);
  EXPECT_EQ(log.contacts[0].speed_m_s, 0.0);  // a stroke's first report has no speed yet
  EXPECT_NEAR(log.contacts[0].force_n, 0.5 * kDefaultFullScaleN, 1e-12);
  EXPECT_NEAR(log.contacts[1].speed_m_s, 0.1, 1e-9);  // 1 mm in 10 ms
  EXPECT_NEAR(log.contacts[2].speed_m_s, 0.1, 1e-9);
  EXPECT_EQ(log.contacts[3].speed_m_s, 0.0);
  EXPECT_EQ(log.contacts[3].force_n, 0.0);
  EXPECT_EQ(log.contacts[3].time_s, 1.040);
  EXPECT_FALSE(contact.status().in_stroke);
  EXPECT_EQ(contact.status().strokes, 1u);
}

// Proximity out without a tip up, and the tablet unplugged mid-stroke, end the stroke as cleanly.
TEST(PenContact, ProximityOutAndTheTabletRemovedEndTheStroke) {
  PenContactLog log;
  PenContact contact(default_pressure_curve(), log.events_to_log());
  contact.on_sample(pen_contact_report(2.00, 0.010, 0.3, true));
  contact.on_sample(pen_contact_report(2.01, 0.011, 0.3, true, false));
  contact.on_sample(pen_contact_report(3.00, 0.010, 0.3, true));
  contact.on_removed();
  contact.on_removed();  // nothing more to end
  EXPECT_EQ(log.events,
            (std::vector<std::string>{"began 1", "contact", "contact", "ended 1 out of proximity",
                                      "began 2", "contact", "contact", "ended 2 tablet removed"}));
  EXPECT_EQ(log.contacts.back().speed_m_s, 0.0);
  EXPECT_EQ(log.contacts.back().force_n, 0.0);
}

// The engine gets the stroke's speed and force: 80 mm/s along a line (133 Hz, ±0.5 ms, 0.01 mm)
// under pressure 0.4 of the default curve. Each speed from the third report on within −7.3 %/+8.4 %
// of 80 mm/s, the worst the tablet's imperfections allow (pen_speed_test.cpp derives it); the
// force exact, as the pressure is.
TEST(PenContact, EachReportGivesTheStrokesSpeedAndForce) {
  PenContactLog log;
  PenContact contact(default_pressure_curve(), log.events_to_log());
  const auto reports =
      testing::synthetic_stroke(testing::straight_line(0.080), 1.0, testing::TabletModel{});
  for (const auto& r : reports) contact.on_sample(r.sample);
  ASSERT_EQ(log.contacts.size(), reports.size());
  for (std::size_t i = 2; i < log.contacts.size(); ++i) {
    EXPECT_GT(log.contacts[i].speed_m_s, 0.080 * (1 - 0.073)) << i;
    EXPECT_LT(log.contacts[i].speed_m_s, 0.080 * (1 + 0.084)) << i;
    EXPECT_NEAR(log.contacts[i].force_n, 0.4 * kDefaultFullScaleN, 1e-12);
    EXPECT_EQ(log.contacts[i].time_s, reports[i].sample.time_s);
  }
  const PenContactStatus status = contact.status();
  EXPECT_TRUE(status.in_stroke);
  EXPECT_NEAR(status.report_interval_s, 1.0 / 133.0, 0.25e-3);
  EXPECT_EQ(status.lag_s, status.report_interval_s);
}

// A pen pressed but held still sends nothing: the tick that finds it silent past the timeout gives
// speed 0 once, the force held; the next report moves it again.
TEST(PenContact, APenHeldStillFallsToSpeedZeroOnTheTickAndKeepsItsForce) {
  PenContactLog log;
  PenContact contact(default_pressure_curve(), log.events_to_log());
  const double period = 1.0 / 133.0;
  for (int k = 0; k < 20; ++k)
    contact.on_sample(pen_contact_report(5.0 + k * period, 0.01 + k * 0.0005, 0.4, true));
  const double last = 5.0 + 19 * period;
  const std::size_t moving = log.contacts.size();
  contact.tick(last + 2.0 * period);
  EXPECT_EQ(log.contacts.size(), moving) << "a report two intervals late is not a stop";
  contact.tick(last + 3.0 * period);
  ASSERT_EQ(log.contacts.size(), moving + 1);
  EXPECT_EQ(log.contacts.back().speed_m_s, 0.0);
  EXPECT_NEAR(log.contacts.back().force_n, 0.4 * kDefaultFullScaleN, 1e-12);
  EXPECT_EQ(log.contacts.back().time_s, last + 3.0 * period);
  contact.tick(last + 4.0 * period);
  EXPECT_EQ(log.contacts.size(), moving + 1);
  contact.on_sample(pen_contact_report(last + 5.0 * period, 0.01 + 20 * 0.0005, 0.4, true));
  EXPECT_GT(log.contacts.back().speed_m_s, 0.0);
  EXPECT_TRUE(contact.status().in_stroke);
}

// Reports from a reader thread and ticks from another: the callbacks never run two at a time, and
// every stroke ends at speed and force 0.
TEST(PenContact, ReaderAndTickThreadsNeverCallBackAtOnce) {
  std::atomic<int> inside{0};
  std::atomic<int> overlaps{0};
  std::atomic<std::uint64_t> began{0}, ended{0};
  PenContactSample last{};
  PenContactEvents events;
  events.contact = [&](const PenContactSample& c) {
    if (inside.fetch_add(1) != 0) ++overlaps;
    last = c;
    inside.fetch_sub(1);
  };
  events.stroke_began = [&](std::uint64_t) { ++began; };
  events.stroke_ended = [&](std::uint64_t, PenStrokeEnd) { ++ended; };
  PenContact contact(default_pressure_curve(), events);
  std::atomic<bool> done{false};
  std::thread ticker([&] {
    while (!done) contact.tick(pen_clock_now_s());
  });
  std::thread reader([&] {
    for (int stroke = 0; stroke < 20; ++stroke) {
      for (int k = 0; k < 50; ++k)
        contact.on_sample(pen_contact_report(pen_clock_now_s(), 0.01 + k * 1e-4, 0.3, k < 49));
    }
  });
  reader.join();
  done = true;
  ticker.join();
  EXPECT_EQ(overlaps.load(), 0);
  EXPECT_EQ(began.load(), 20u);
  EXPECT_EQ(ended.load(), 20u);
  EXPECT_EQ(last.speed_m_s, 0.0);
  EXPECT_EQ(last.force_n, 0.0);
}

double pen_block_rms(const std::vector<float>& x) {
  double sum = 0.0;
  for (float v : x) sum += static_cast<double>(v) * v;
  return std::sqrt(sum / static_cast<double>(x.size()));
}

// Into a real engine (the crayon on office paper, rendered block by block as a device would): it
// sounds while the pen draws and falls silent once the tip is up.
TEST(PenContact, TheEngineSoundsDuringAStrokeAndFallsSilentAfterIt) {
  rt::EngineSettings settings;
  settings.slots = 1;
  playback::PreparedEngine session(settings, nibrig::rig::testing::bundled_sound("cryon", "office"),
                                   std::make_unique<rt::ConstantStroke>(0.0, 0.0), 1);
  rt::Engine& engine = session.engine();
  PenContactEvents events;
  events.contact = [&engine](const PenContactSample& c) {
    engine.set_contact(c.speed_m_s, c.force_n);
  };
  PenContact contact(default_pressure_curve(), events);
  std::vector<float> block(64);
  const auto reports =
      testing::synthetic_stroke(testing::straight_line(0.080), 0.5, testing::TabletModel{});
  double sounding = 0.0;
  for (std::size_t i = 0; i < reports.size(); ++i) {
    contact.on_sample(reports[i].sample);
    // 48 kHz blocks of 64 between reports at 133 Hz: about 5.6 blocks a report.
    for (int b = 0; b < 6; ++b) {
      engine.render(block.data(), block.size());
      if (i > reports.size() / 2) sounding = std::max(sounding, pen_block_rms(block));
    }
  }
  EXPECT_GT(sounding, 1e-4);
  PenSample up = reports.back().sample;
  up.time_s += 1.0 / 133.0;
  up.tip_down = false;
  contact.on_sample(up);
  double after = 0.0;
  for (int b = 0; b < 1500; ++b) engine.render(block.data(), block.size());  // 2 s to ring down
  for (int b = 0; b < 50; ++b) {
    engine.render(block.data(), block.size());
    after = std::max(after, pen_block_rms(block));
  }
  EXPECT_LT(after, 1e-6);
}

}  // namespace
}  // namespace nibrig::rig::pen
