// Importer for the artists' pen trajectories of the seed paper
// (../shared/data/piovarci2018/drawing): real stylus position, speed, force and touch over time, in
// SI units, to drive the real-time engine with how people actually draw.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace nibrig::model::io {

struct DrawingTrajectory {
  std::string tool, surface, subject;  // <tool>_<surface>_<subject>.csv[.gz]; subject may hold '_'
  std::filesystem::path source;
  // Frames per second while tracking: frame steps of up to 50 ms divided by the time they cover.
  // Nothing downstream assumes a rate: rt::TrajectoryStroke interpolates between the stamps.
  double frame_rate_hz = 0.0;
  std::vector<double> time_s, x_m, y_m, normal_force_N;
  std::vector<bool> touching;
  // The Speed column is the in-plane distance between consecutive frames in mm/frame; times the
  // frame rate it is mm/s, stored in m/s.
  std::vector<double> speed_m_s;
  std::vector<std::string> warnings;  // a cut-off last row that was dropped
};

// Header `Unix Timestamp,X,Y,Z,Phi,Theta,F,Ground,Touch,Speed,Acceeration` (sic): Unix time in ms,
// position in mm, force in N, touch 0/1, speed in mm/frame.
//
// Why not the median of 1/Δt: the stamps have 1 ms resolution and jitter between 6, 7 and 8 ms,
// so the median lands on 125.0 or 142.9 Hz depending on which step happens to be commonest, up to
// 25 % above the true frame rate (about 111-139 Hz across the files). Steps longer than 50 ms are
// tracking dropouts (pen out of range) and are left out.
// Throws FormatError "expected about 120 Hz (the paper's tracker) or a pen tablet's 100-300 Hz
// (30-500 Hz accepted) ..." for a frame rate outside 30-500 Hz: the paper's files measure
// 111-139 Hz, strokes recorded from pen tablets (rig/pen's StrokeRecorder) their report rate,
// 100-300 Hz; stamps 1 ms apart (1000 Hz) are no tablet's.
DrawingTrajectory read_paper_drawing(const std::filesystem::path& file);

}  // namespace nibrig::model::io
