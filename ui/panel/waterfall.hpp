// A scrolling spectrogram, the way live waterfall tools draw one: each new spectrum becomes a row of
// colours in a ring (on the UI thread, from rows an analysis thread made), only the new rows are
// uploaded into an OpenGL texture, and the texture is drawn with wrapped texture coordinates so
// that the newest row is on top without moving any pixels.
#pragma once

#include <cstdint>
#include <vector>

#include "imgui.h"

namespace nibrig::ui::panel {

struct Rgba {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
  bool operator==(const Rgba&) const = default;
};

// Viridis (ui/report/colour_maps.hpp: perceptually uniform, readable in grey) of value in [lo, hi],
// clamped.
Rgba sequential_colour(float value, float lo, float hi);
// Blue (−span) through near-white (0) to red (+span), clamped: a difference in dB.
Rgba diverging_colour(float value, float span);

class Waterfall {
 public:
  enum class Scale { sequential, diverging };
  // bins columns, rows kept; sequential: colours from lo_db to hi_db; diverging: ±hi_db.
  Waterfall(std::size_t bins, std::size_t rows, Scale scale, float lo_db, float hi_db);
  ~Waterfall();
  Waterfall(const Waterfall&) = delete;
  Waterfall& operator=(const Waterfall&) = delete;

  // One spectrum of bins() values in dB becomes the newest row.
  void push_row(const float* db);
  std::size_t bins() const { return bins_; }
  std::size_t rows() const { return rows_; }
  std::uint64_t rows_pushed() const { return pushed_; }
  // The colour of a bin in the row `age` rows older than the newest (0: the newest).
  Rgba colour_at(std::size_t age, std::size_t bin) const;

  // With the window's OpenGL context current: uploads what changed since the last draw, then draws
  // the waterfall into [min, max] (newest row at the top). Without one, draws nothing.
  void draw(ImDrawList* draw, ImVec2 min, ImVec2 max);

 private:
  void upload();

  std::size_t bins_, rows_;
  Scale scale_;
  float lo_db_, hi_db_;
  std::vector<Rgba> pixels_;  // rows × bins, row-major; row r of the ring
  std::size_t head_ = 0;      // the row the next push writes
  std::uint64_t pushed_ = 0, uploaded_ = 0;
  unsigned texture_ = 0;
};

}  // namespace nibrig::ui::panel
