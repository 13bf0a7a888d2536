// The pen as the engine's live contact: tip down starts a stroke; each report during it gives the
// tip's speed (PenSpeed) and normal force (the pen's PressureCurve); tip up, proximity out or the
// tablet removed ends it, and speed and force go to 0. What it gives goes out through callbacks,
// for a face to post to rt::Engine::set_contact (through playback::LiveAudition) and to draw.
//
// Threads: on_sample and on_removed come from the pen reader's thread (PenEvents, pen_input.hpp);
// tick from any thread, e.g. a face's timer or frame, so that a pen held still (libinput then sends
// nothing) reaches speed 0 at the first tick past PenSpeed's still timeout. Every call takes one
// mutex and calls back under it, so that the callbacks see the stroke's contacts in order and never
// two at a time: keep them short (a post to a queue), and never call this object from them. They
// run on the reader's thread and the tick's: playback::LiveAudition takes calls from one thread,
// so a face hands the contact to the thread that owns it, or makes every call to it under one lock.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>

#include "rig/pen/pen_force.hpp"
#include "rig/pen/pen_sample.hpp"
#include "rig/pen/pen_speed.hpp"

namespace nibrig::rig::pen {

struct PenContactSample {
  double time_s = 0.0;  // the report's kernel stamp; a tick's time for a tick's zero speed
  double speed_m_s = 0.0;
  double force_n = 0.0;
  double pressure = 0.0;  // the pressure the force was made from
};

enum class PenStrokeEnd { tip_up, out_of_proximity, tablet_removed };
const char* pen_stroke_end_name(PenStrokeEnd why) noexcept;

struct PenContactEvents {
  // Each report during a stroke, the tick that finds the pen held still, and the stroke's end
  // (speed and force 0).
  std::function<void(const PenContactSample&)> contact;
  // Stroke numbers count from 1 for this object's life. began comes before the stroke's first
  // contact, ended after its last.
  std::function<void(std::uint64_t stroke)> stroke_began;
  std::function<void(std::uint64_t stroke, PenStrokeEnd why)> stroke_ended;
};

struct PenContactStatus {
  bool in_stroke = false;
  std::uint64_t strokes = 0;                    // begun so far
  PenContactSample last;                        // the newest contact given
  double report_interval_s = 0.0, lag_s = 0.0;  // PenSpeed's measured interval and its lag
  std::size_t skipped_reports = 0;              // stamps that did not move forward
};

class PenContact {
 public:
  PenContact(PressureCurve curve, PenContactEvents events);

  void on_sample(const PenSample& sample);
  void on_removed();
  // `now_s` on the reports' clock (pen_clock_now_s()). Gives a contact of speed 0 once, when the
  // pen has sent nothing for PenSpeed's still timeout.
  void tick(double now_s);

  PenContactStatus status() const;

 private:
  void end_stroke(PenStrokeEnd why, double time_s);
  void give(const PenContactSample& contact);

  mutable std::mutex mutex_;
  const PressureCurve curve_;
  const PenContactEvents events_;
  PenSpeed speed_;
  bool in_stroke_ = false;
  bool still_given_ = false;  // the tick gave this stroke's held-still zero since the last report
  std::uint64_t strokes_ = 0;
  PenContactSample last_;
};

}  // namespace nibrig::rig::pen
