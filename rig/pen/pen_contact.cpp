#include "rig/pen/pen_contact.hpp"

#include <utility>

namespace nibrig::rig::pen {

const char* pen_stroke_end_name(PenStrokeEnd why) noexcept {
  switch (why) {
    case PenStrokeEnd::tip_up:
      return "tip up";
    case PenStrokeEnd::out_of_proximity:
      return "out of proximity";
    case PenStrokeEnd::tablet_removed:
      return "tablet removed";
  }
  return "?";
}

PenContact::PenContact(PressureCurve curve, PenContactEvents events)
    : curve_(std::move(curve)), events_(std::move(events)) {}

void PenContact::give(const PenContactSample& contact) {
  last_ = contact;
  if (events_.contact) events_.contact(contact);
}

void PenContact::end_stroke(PenStrokeEnd why, double time_s) {
  if (!in_stroke_) return;
  in_stroke_ = false;
  speed_.reset();
  give({time_s, 0.0, 0.0, 0.0});
  if (events_.stroke_ended) events_.stroke_ended(strokes_, why);
}

void PenContact::on_sample(const PenSample& sample) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (!sample.in_proximity) {
    end_stroke(PenStrokeEnd::out_of_proximity, sample.time_s);
    return;
  }
  if (!sample.tip_down) {
    end_stroke(PenStrokeEnd::tip_up, sample.time_s);
    return;
  }
  if (!in_stroke_) {
    in_stroke_ = true;
    ++strokes_;
    speed_.reset();
    if (events_.stroke_began) events_.stroke_began(strokes_);
  }
  still_given_ = false;
  const double speed = speed_.add(sample.time_s, sample.x_m, sample.y_m);
  give({sample.time_s, speed, curve_.force_n(sample.pressure), sample.pressure});
}

void PenContact::on_removed() {
  const std::lock_guard<std::mutex> lock(mutex_);
  end_stroke(PenStrokeEnd::tablet_removed, last_.time_s);
}

void PenContact::tick(double now_s) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (!in_stroke_ || still_given_ || speed_.speed_at(now_s) != 0.0 || last_.speed_m_s == 0.0)
    return;
  still_given_ = true;
  PenContactSample still = last_;
  still.time_s = now_s;
  still.speed_m_s = 0.0;
  give(still);
}

PenContactStatus PenContact::status() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  PenContactStatus s;
  s.in_stroke = in_stroke_;
  s.strokes = strokes_;
  s.last = last_;
  s.report_interval_s = speed_.report_interval_s();
  s.lag_s = speed_.lag_s();
  s.skipped_reports = speed_.skipped();
  return s;
}

}  // namespace nibrig::rig::pen
