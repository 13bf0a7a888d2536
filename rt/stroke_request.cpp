#include "rt/stroke_request.hpp"

#include <fmt/format.h>

#include "model/io/paper_drawing.hpp"

namespace nibrig::rt {

Stroke make_stroke(const StrokeRequest& r) {
  Stroke stroke;
  const double force = r.force_n.value_or(kReferenceNormalForce);
  if (r.speed_m_s) {
    stroke.source = std::make_unique<ConstantStroke>(*r.speed_m_s, force);
    // Not to_string().substr(), which cut 1e9 mm/s down to "100000".
    stroke.description = fmt::format("constant {:.2f} mm/s", *r.speed_m_s * 1000.0);
    stroke.natural_seconds = 5.0;
  } else if (!r.trajectory.empty()) {
    const auto drawing = model::io::read_paper_drawing(r.trajectory);
    auto source = r.force_n ? std::make_unique<TrajectoryStroke>(drawing, force)
                            : std::make_unique<TrajectoryStroke>(drawing);
    stroke.natural_seconds = source->duration();
    stroke.source = std::move(source);
    stroke.description = "trajectory " + r.trajectory.filename().string();
  } else {
    stroke.source = std::make_unique<SweepStroke>(SweepStroke::kPaperLow, SweepStroke::kPaperHigh,
                                                  SweepStroke::kPaperPeriod, force);
    stroke.description = "sweep 17-250 mm/s, 3 s period";
    stroke.natural_seconds = 2 * SweepStroke::kPaperPeriod;
  }
  if (r.force_n) stroke.description += fmt::format(", {:.3f} N", *r.force_n);
  return stroke;
}

}  // namespace nibrig::rt
