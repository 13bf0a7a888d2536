// One PNG being drawn with PLplot: holds the process-wide PLplot lock, a fresh PLplot stream and
// the temporary file, and offers drawing in page pixels (origin at the bottom left, y up). Only the
// figure sources of ui/report include this; PLplot's headers stay out of the public interface.
#pragma once

#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "model/io/atomic_file.hpp"
#include "ui/report/colour_maps.hpp"

namespace nibrig::ui::report::detail {

// Throws std::runtime_error if PLplot's pngcairo device cannot be loaded (checked without letting
// PLplot's own search run, since PLplot ends the process when it finds no driver).
void require_pngcairo();

class PlotPage {
 public:
  // Locks, checks the device, creates the temporary file beside png and starts a stream drawing
  // into it. `name` (the figure's title) names the figure in error messages.
  PlotPage(std::string name, const std::filesystem::path& png, int width_px, int height_px);
  ~PlotPage();
  PlotPage(const PlotPage&) = delete;
  PlotPage& operator=(const PlotPage&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }

  void colour(Rgb c, double alpha = 1.0);
  void line_width(double px);
  // Lines drawn next are dashed: alternating dash and gap lengths in px; empty for solid lines.
  void dashes(const std::vector<double>& on_off_px);
  void polyline(const std::vector<double>& x, const std::vector<double>& y);
  void segment(double x0, double y0, double x1, double y1);
  void fill(const std::vector<double>& x, const std::vector<double>& y);
  void rectangle(double x0, double y0, double x1, double y1);  // filled
  void disc(double x, double y, double radius);                // filled
  // Text with its reference point at (x, y): `just` 0 puts the start there, 0.5 the middle, 1 the
  // end; vertically the reference is the middle of the capitals. angle_deg turns it anticlockwise.
  void text(double x, double y, double angle_deg, double just, double cap_px, const std::string& s);

  // Fills the box [x0, x1] × [y0, y1] (page pixels) with cells: cell (i, j) spans x_edges[i..i+1] ×
  // y_edges[j..j+1] of the window [x_edges.front(), x_edges.back()] × [y_edges.front(), ...], and
  // takes the viridis colour of t[j][i] in [0, 1].
  void cells(double x0, double y0, double x1, double y1, const std::vector<double>& x_edges,
             const std::vector<double>& y_edges, const std::vector<std::vector<double>>& t);

  // Ends the stream, checks what PLplot reported, and renames the temporary file onto png.
  void commit();

 private:
  void page_space();
  void finish_stream();

  std::unique_lock<std::mutex> lock_;
  std::string name_;
  std::filesystem::path png_;
  model::io::OutputTarget target_;
  std::filesystem::path temporary_;
  int width_, height_;
  int stream_ = -1;
  int previous_stream_ = 0;
  bool stream_open_ = false;
  bool committed_ = false;
  int error_code_ = 0;
  char error_message_[1024] = {};
};

}  // namespace nibrig::ui::report::detail
