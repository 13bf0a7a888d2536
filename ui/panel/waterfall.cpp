#include "ui/panel/waterfall.hpp"

#include "ui/panel/panel_window.hpp"

#define GL_GLEXT_PROTOTYPES
#include <GLFW/glfw3.h>
#include <GL/glext.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "ui/report/colour_maps.hpp"

namespace nibrig::ui::panel {

namespace {

std::uint8_t byte(float v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

}  // namespace

Rgba sequential_colour(float value, float lo, float hi) {
  const report::Rgb c = report::viridis_at((value - lo) / (hi - lo));  // clamped, NaN as the low end
  return {static_cast<std::uint8_t>(c.r), static_cast<std::uint8_t>(c.g), static_cast<std::uint8_t>(c.b), 255};
}

Rgba diverging_colour(float value, float span) {
  float u = value / span;
  if (!std::isfinite(u)) u = 0.0f;
  u = std::clamp(u, -1.0f, 1.0f);
  const float w = 0.95f;  // the colour of zero: no difference
  if (u >= 0) return {byte(w + u * (0.80f - w)), byte(w + u * (0.10f - w)), byte(w + u * (0.15f - w)), 255};
  return {byte(w - u * (0.10f - w)), byte(w - u * (0.30f - w)), byte(w - u * (0.75f - w)), 255};
}

Waterfall::Waterfall(std::size_t bins, std::size_t rows, Scale scale, float lo_db, float hi_db)
    : bins_(bins), rows_(rows), scale_(scale), lo_db_(lo_db), hi_db_(hi_db) {
  if (bins == 0 || rows == 0) throw std::invalid_argument("a waterfall needs at least one bin and one row");
  const Rgba empty = scale == Scale::sequential ? sequential_colour(lo_db, lo_db, hi_db) : diverging_colour(0, 1);
  pixels_.assign(bins * rows, empty);
}

Waterfall::~Waterfall() {
  if (texture_) glDeleteTextures(1, &texture_);
}

void Waterfall::push_row(const float* db) {
  Rgba* row = pixels_.data() + head_ * bins_;
  for (std::size_t k = 0; k < bins_; ++k)
    row[k] = scale_ == Scale::sequential ? sequential_colour(db[k], lo_db_, hi_db_) : diverging_colour(db[k], hi_db_);
  head_ = (head_ + 1) % rows_;
  ++pushed_;
}

Rgba Waterfall::colour_at(std::size_t age, std::size_t bin) const {
  const std::size_t r = (head_ + rows_ - 1 - age % rows_) % rows_;
  return pixels_[r * bins_ + bin];
}

void Waterfall::upload() {
  if (!texture_) {
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);  // the ring scrolls by coordinates
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, static_cast<GLsizei>(bins_), static_cast<GLsizei>(rows_), 0,
                 GL_RGBA, GL_UNSIGNED_BYTE, pixels_.data());
    uploaded_ = pushed_;
    return;
  }
  if (uploaded_ == pushed_) return;
  PanelWindow::contents_changed();  // new rows under the same draw commands
  glBindTexture(GL_TEXTURE_2D, texture_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  // Only the rows pushed since the last upload (all of them if more than the ring holds).
  const std::size_t fresh = static_cast<std::size_t>(std::min<std::uint64_t>(pushed_ - uploaded_, rows_));
  for (std::size_t i = 0; i < fresh; ++i) {
    const std::size_t r = (head_ + rows_ - fresh + i) % rows_;
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, static_cast<GLint>(r), static_cast<GLsizei>(bins_), 1, GL_RGBA,
                    GL_UNSIGNED_BYTE, pixels_.data() + r * bins_);
  }
  uploaded_ = pushed_;
}

void Waterfall::draw(ImDrawList* draw, ImVec2 min, ImVec2 max) {
  if (!glfwGetCurrentContext()) return;  // no window (the headless tests): nothing to draw into
  upload();
  // Row r spans v in [r, r+1) / rows; the newest (head − 1) ends at v = head / rows, drawn at the top.
  const float top = static_cast<float>(head_) / static_cast<float>(rows_);
  // The bottom edge stops half a texel short of wrapping round to the newest row again.
  draw->AddImage(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(texture_)), min, max, {0.0f, top},
                 {1.0f, top - 1.0f + 0.5f / static_cast<float>(rows_)});
}

}  // namespace nibrig::ui::panel
