#include "ui/panel/panel_window.hpp"

#define GL_GLEXT_PROTOTYPES
#include <GLFW/glfw3.h>
#include <GL/glext.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "backends/imgui_impl_glfw.h"
#include "backends/imgui_impl_opengl3.h"
#include "imgui.h"
#include "ui/panel/background_job.hpp"

namespace nibrig::ui::panel {

namespace {

// Set when the window system asks for the window's contents again (uncovered, resized): the next
// frame renders even if nothing in it changed.
std::atomic<bool> contents_lost{true};

// FNV-1a over what a frame draws: every vertex, index and command (clip rectangle, texture,
// counts), and the display's size.
std::uint64_t draw_data_hash(const ImDrawData* data) {
  std::uint64_t h = 1469598103934665603ULL;
  const auto mix = [&h](const void* bytes, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(bytes);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ULL;
  };
  mix(&data->DisplaySize, sizeof data->DisplaySize);
  mix(&data->FramebufferScale, sizeof data->FramebufferScale);
  for (int l = 0; l < data->CmdListsCount; ++l) {
    const ImDrawList* list = data->CmdLists[l];
    mix(list->VtxBuffer.Data, static_cast<std::size_t>(list->VtxBuffer.Size) * sizeof(ImDrawVert));
    mix(list->IdxBuffer.Data, static_cast<std::size_t>(list->IdxBuffer.Size) * sizeof(ImDrawIdx));
    for (const ImDrawCmd& cmd : list->CmdBuffer) {
      mix(&cmd.ClipRect, sizeof cmd.ClipRect);
      mix(&cmd.TextureId, sizeof cmd.TextureId);
      mix(&cmd.VtxOffset, sizeof cmd.VtxOffset);
      mix(&cmd.IdxOffset, sizeof cmd.IdxOffset);
      mix(&cmd.ElemCount, sizeof cmd.ElemCount);
      const bool callback = cmd.UserCallback != nullptr;
      mix(&callback, sizeof callback);
    }
  }
  return h;
}

std::string glfw_error() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? description : "no reason given";
}

}  // namespace

PanelWindow::PanelWindow(const WindowSettings& settings) {
  if (!glfwInit()) {
    const char* display = std::getenv("DISPLAY");
    throw std::runtime_error("the panel cannot open a window: " + glfw_error() +
                             (display && *display ? std::string()
                                                  : " (no DISPLAY: on a machine without a screen run it "
                                                    "under `xvfb-run -a`)"));
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_VISIBLE, settings.visible ? GLFW_TRUE : GLFW_FALSE);
  window_ = glfwCreateWindow(settings.width, settings.height, settings.title.c_str(), nullptr, nullptr);
  if (!window_) {
    const std::string why = glfw_error();
    glfwTerminate();
    throw std::runtime_error("the panel cannot open an OpenGL 3.3 core window: " + why);
  }
  glfwSetWindowSizeLimits(window_, kMinWidth, kMinHeight, GLFW_DONT_CARE, GLFW_DONT_CARE);
  skip_unchanged_ = settings.skip_unchanged;
  glfwSetWindowRefreshCallback(window_, [](GLFWwindow*) { contents_lost = true; });
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(settings.vsync ? 1 : 0);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  ini_file_ = settings.ini_file.string();
  io.IniFilename = ini_file_.empty() ? nullptr : ini_file_.c_str();
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
  // Keys and characters go through keys_ (key_queue.hpp): ImGui's callbacks, just installed, are
  // called from begin_frame instead of from the event poll.
  glfwSetWindowUserPointer(window_, this);
  imgui_key_ = glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int scancode, int action, int mods) {
    static_cast<PanelWindow*>(glfwGetWindowUserPointer(w))
        ->keys_.push({KeyEvent::Kind::key, key, scancode, action, mods, 0});
  });
  imgui_char_ = glfwSetCharCallback(window_, [](GLFWwindow* w, unsigned int codepoint) {
    static_cast<PanelWindow*>(glfwGetWindowUserPointer(w))
        ->keys_.push({KeyEvent::Kind::character, 0, 0, 0, 0, codepoint});
  });
  job_done_hook = &PanelWindow::wake;
}

PanelWindow::~PanelWindow() {
  job_done_hook = nullptr;
  // ImGui's shutdown puts back what was there before its own callbacks.
  glfwSetKeyCallback(window_, imgui_key_);
  glfwSetCharCallback(window_, imgui_char_);
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window_);
  glfwTerminate();
}

bool PanelWindow::should_close() const { return glfwWindowShouldClose(window_); }

bool PanelWindow::wait_events(double timeout_s) {
  if (keys_.waiting() > 0) {
    // A held-back release must come on the next frame, not after a second's sleep (ImGui would
    // count the key as held that long, and repeat it in a text field).
    return true;
  }
  const auto start = std::chrono::steady_clock::now();
  glfwWaitEventsTimeout(timeout_s);
  // GLFW does not say why the wait ended: one that ended early had an event.
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < timeout_s * 0.9;
}

void PanelWindow::wake() { glfwPostEmptyEvent(); }

void PanelWindow::contents_changed() { contents_lost = true; }

void PanelWindow::begin_frame(const std::function<void(ImGuiIO&)>& input) {
  glfwPollEvents();
  keys_.deliver([this](const KeyEvent& e) {
    if (e.kind == KeyEvent::Kind::key) {
      if (imgui_key_) imgui_key_(window_, e.key, e.scancode, e.action, e.mods);
    } else if (imgui_char_) {
      imgui_char_(window_, e.codepoint);
    }
  });
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  if (input) input(ImGui::GetIO());
  ImGui::NewFrame();
}

void PanelWindow::end_frame(const std::filesystem::path& screenshot) {
  ImGui::Render();
  if (skip_unchanged_ && screenshot.empty()) {
    const std::uint64_t hash = draw_data_hash(ImGui::GetDrawData());
    if (hash == shown_hash_ && !contents_lost.exchange(false)) {
      ++skipped_;
      return;
    }
    shown_hash_ = hash;
  }
  ++rendered_;
  const int width = framebuffer_width(), height = framebuffer_height();
  glViewport(0, 0, width, height);
  glClearColor(0.08f, 0.08f, 0.09f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  if (!screenshot.empty()) write_framebuffer_png(screenshot, width, height);
  glfwSwapBuffers(window_);
}

int PanelWindow::framebuffer_width() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return w;
}

int PanelWindow::framebuffer_height() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return h;
}

void write_framebuffer_png(const std::filesystem::path& file, int width, int height) {
  std::vector<unsigned char> pixels(static_cast<std::size_t>(width) * height * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_BACK);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
  std::vector<unsigned char> flipped(pixels.size());
  const std::size_t row = static_cast<std::size_t>(width) * 3;
  for (int y = 0; y < height; ++y)
    std::copy_n(pixels.data() + static_cast<std::size_t>(height - 1 - y) * row, row,
                flipped.data() + static_cast<std::size_t>(y) * row);
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  if (!stbi_write_png(file.c_str(), width, height, 3, flipped.data(), static_cast<int>(row)))
    throw std::runtime_error(file.string() + ": the screenshot cannot be written there");
}

}  // namespace nibrig::ui::panel
