// A part of a view that changes only when its inputs do (the space's regions and grid: hundreds of
// ellipses) painted once into an OpenGL texture and drawn as one image every frame after: on a
// software rasteriser (Mesa's llvmpipe) hundreds of ellipses drawn live are much of a frame.
// Without an OpenGL context (the headless tests) it is not available and views paint live.
#pragma once

#include <cstdint>
#include <functional>

#include "imgui.h"

namespace nibrig::ui::panel {

class CachedLayer {
 public:
  CachedLayer() = default;
  ~CachedLayer();
  CachedLayer(const CachedLayer&) = delete;
  CachedLayer& operator=(const CachedLayer&) = delete;

  // Whether there is a context to paint into.
  static bool available();
  // Paints the rectangle [origin, origin + size) (screen coordinates) anew when `key` differs from
  // the last one: cleared to `background` (opaque), then `paint` on a draw list of its own.
  void update(std::uint64_t key, ImVec2 origin, ImVec2 size, ImU32 background,
              const std::function<void(ImDrawList*)>& paint);
  // The last painting, at its rectangle.
  void draw(ImDrawList* draw) const;
  std::uint64_t paintings() const { return paintings_; }

 private:
  unsigned framebuffer_ = 0, texture_ = 0;
  int width_ = 0, height_ = 0;
  ImVec2 origin_{}, size_{};
  std::uint64_t key_ = 0, paintings_ = 0;
};

}  // namespace nibrig::ui::panel
