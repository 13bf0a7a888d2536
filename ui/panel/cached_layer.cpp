#include "ui/panel/cached_layer.hpp"

#include "ui/panel/panel_window.hpp"

#define GL_GLEXT_PROTOTYPES
#include <GLFW/glfw3.h>
#include <GL/glext.h>

#include <cmath>

#include "backends/imgui_impl_opengl3.h"

namespace nibrig::ui::panel {

bool CachedLayer::available() { return glfwGetCurrentContext() != nullptr; }

CachedLayer::~CachedLayer() {
  if (!available()) return;
  if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
  if (texture_) glDeleteTextures(1, &texture_);
}

void CachedLayer::update(std::uint64_t key, ImVec2 origin, ImVec2 size, ImU32 background,
                         const std::function<void(ImDrawList*)>& paint) {
  const int width = static_cast<int>(std::lround(size.x)), height = static_cast<int>(std::lround(size.y));
  if (paintings_ && key == key_ && width == width_ && height == height_ && origin.x == origin_.x &&
      origin.y == origin_.y)
    return;
  if (width <= 0 || height <= 0) return;
  GLint previous_framebuffer = 0, previous_viewport[4] = {};
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous_framebuffer);
  glGetIntegerv(GL_VIEWPORT, previous_viewport);
  if (!texture_ || width != width_ || height != height_) {
    if (!texture_) glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_A, GL_ONE);  // opaque, whatever blending left in alpha
    if (!framebuffer_) glGenFramebuffers(1, &framebuffer_);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, 0);
    width_ = width;
    height_ = height;
  }
  PanelWindow::contents_changed();  // the texture's pixels change under the same draw commands
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, width, height);
  const ImVec4 bg = ImGui::ColorConvertU32ToFloat4(background);
  glClearColor(bg.x, bg.y, bg.z, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);

  ImDrawList list(ImGui::GetDrawListSharedData());
  list._ResetForNewFrame();
  list.Flags = ImDrawListFlags_AntiAliasedLines | ImDrawListFlags_AntiAliasedLinesUseTex | ImDrawListFlags_AntiAliasedFill;
  list.PushTextureID(ImGui::GetIO().Fonts->TexID);
  list.PushClipRect(origin, {origin.x + size.x, origin.y + size.y});
  paint(&list);
  ImDrawList* lists[] = {&list};
  ImDrawData data;
  data.Valid = true;
  data.CmdLists = lists;
  data.CmdListsCount = 1;
  data.TotalVtxCount = list.VtxBuffer.Size;
  data.TotalIdxCount = list.IdxBuffer.Size;
  data.DisplayPos = origin;
  data.DisplaySize = {static_cast<float>(width), static_cast<float>(height)};
  data.FramebufferScale = {1.0f, 1.0f};
  ImGui_ImplOpenGL3_RenderDrawData(&data);

  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous_framebuffer));
  glViewport(previous_viewport[0], previous_viewport[1], previous_viewport[2], previous_viewport[3]);
  key_ = key;
  origin_ = origin;
  size_ = {static_cast<float>(width), static_cast<float>(height)};
  ++paintings_;
}

void CachedLayer::draw(ImDrawList* draw) const {
  if (!paintings_) return;
  // The framebuffer's rows run bottom-up: the image is drawn flipped.
  draw->AddImage(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(texture_)), origin_,
                 {origin_.x + size_.x, origin_.y + size_.y}, {0.0f, 1.0f}, {1.0f, 0.0f});
}

}  // namespace nibrig::ui::panel
