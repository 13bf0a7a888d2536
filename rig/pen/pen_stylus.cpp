#include "rig/pen/pen_stylus.hpp"

#include "rig/pen/pen_clock.hpp"

namespace nibrig::rig::pen {
namespace {

constexpr std::size_t kPenTraceLength = 2048;  // about 15 s of reports at 133 a second

// A calibration is stored by pen name; with none given, the tablet's own (full) name is the pen's.
PenCurveChoice stylus_curve(const std::string& tablet, const std::string& pen_name) {
  if (!pen_name.empty()) return pen_curve_for(pen_name);
  const auto tablets = list_tablets();
  const TabletInfo* t = match_tablet(tablets, tablet);
  return pen_curve_for(t ? t->name : tablet);
}

}  // namespace

PenStylus::PenStylus(const std::string& tablet, const std::string& pen_name)
    : curve_(stylus_curve(tablet, pen_name)),
      contact_(curve_.curve, PenContactEvents{
                                 [this](const PenContactSample& c) {
                                   std::lock_guard lock(mutex_);
                                   newest_ = c;
                                   trace_.push_back(c);
                                   if (trace_.size() > kPenTraceLength) trace_.pop_front();
                                 },
                                 [this](std::uint64_t stroke) {
                                   std::lock_guard lock(mutex_);
                                   strokes_.push_back({stroke, true, PenStrokeEnd::tip_up, pen_clock_now_s()});
                                 },
                                 [this](std::uint64_t stroke, PenStrokeEnd why) {
                                   std::lock_guard lock(mutex_);
                                   strokes_.push_back({stroke, false, why, pen_clock_now_s()});
                                 }}) {
  input_ = std::make_unique<PenInput>(tablet, PenEvents{[this](const PenSample& s) {
                                                          contact_.on_sample(s);
                                                          const std::uint64_t stroke = contact_.status().strokes;
                                                          std::function<void(const PenSample&, double)> listener;
                                                          {
                                                            std::lock_guard lock(mutex_);
                                                            listener = listener_;
                                                            if (s.tip_down) {
                                                              path_.push_back({stroke, s.x_m, s.y_m});
                                                              if (path_.size() > kPenTraceLength) path_.pop_front();
                                                            }
                                                          }
                                                          if (listener) listener(s, curve_.curve.force_n(s.pressure));
                                                        },
                                                        [this] { contact_.on_removed(); }});
}

PenStylus::~PenStylus() { input_.reset(); }

const TabletInfo& PenStylus::tablet() const { return input_->tablet(); }
bool PenStylus::removed() const { return input_->removed(); }

std::optional<PenContactSample> PenStylus::take() {
  std::lock_guard lock(mutex_);
  std::optional<PenContactSample> c;
  c.swap(newest_);
  return c;
}

void PenStylus::tick() { contact_.tick(pen_clock_now_s()); }

std::vector<PenStrokeNote> PenStylus::take_strokes() {
  std::lock_guard lock(mutex_);
  std::vector<PenStrokeNote> notes;
  notes.swap(strokes_);
  return notes;
}

std::vector<PenPathPoint> PenStylus::take_path() {
  std::lock_guard lock(mutex_);
  std::vector<PenPathPoint> points(path_.begin(), path_.end());
  path_.clear();
  return points;
}

std::vector<PenContactSample> PenStylus::trace(std::size_t count) const {
  std::lock_guard lock(mutex_);
  const std::size_t n = std::min(count, trace_.size());
  return {trace_.end() - static_cast<std::ptrdiff_t>(n), trace_.end()};
}

void PenStylus::on_sample(std::function<void(const PenSample&, double force_n)> listener) {
  std::lock_guard lock(mutex_);
  listener_ = std::move(listener);
}

}  // namespace nibrig::rig::pen
