// Real key events through the X server, as xdotool sends them: XTest's fake key presses and
// releases from an X client of the test's own, which the server routes to the focused window (the
// panel's GLFW window) like a keyboard's. libX11 and libXtst are opened at run time: their runtime
// libraries come with Xvfb, their headers are not installed (and Xlib's macros would leak into the
// suite's unity units).
#pragma once

#include <dlfcn.h>

#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>

namespace nibrig::ui::panel::testing {

class XKeys {
 public:
  XKeys() {
    x11_ = dlopen("libX11.so.6", RTLD_NOW);
    xtst_ = dlopen("libXtst.so.6", RTLD_NOW);
    if (!x11_ || !xtst_) throw std::runtime_error("XKeys: libX11.so.6 or libXtst.so.6 is not installed");
    load(x11_, "XOpenDisplay", open_);
    load(x11_, "XCloseDisplay", close_);
    load(x11_, "XStringToKeysym", keysym_);
    load(x11_, "XKeysymToKeycode", keycode_);
    load(x11_, "XSync", sync_);
    load(xtst_, "XTestQueryExtension", query_);
    load(xtst_, "XTestFakeKeyEvent", fake_key_);
    display_ = open_(nullptr);
    if (!display_) throw std::runtime_error("XKeys: no X display (DISPLAY unset?)");
    int event = 0, error = 0, major = 0, minor = 0;
    if (!query_(display_, &event, &error, &major, &minor))
      throw std::runtime_error("XKeys: the X server has no XTEST extension");
  }
  ~XKeys() {
    if (display_) close_(display_);
    if (xtst_) dlclose(xtst_);
    if (x11_) dlclose(x11_);
  }
  XKeys(const XKeys&) = delete;
  XKeys& operator=(const XKeys&) = delete;

  // `key` is an X keysym's name: "r", "1", "Return", "Control_L", "Escape".
  void press(const std::string& key) { send(key, true); }
  void release(const std::string& key) { send(key, false); }
  // A press and its release, both in the server before this returns (no frame can come between).
  // Each event follows the one before by kGap: GLFW takes a release and a press of one key that
  // come less than 20 ms apart (server time) for the keyboard's auto-repeat and drops both, as a
  // person's quickest taps of one key never are (no frame is drawn meanwhile either way).
  static constexpr std::chrono::milliseconds kGap{25};
  void tap(const std::string& key) {
    press(key);
    std::this_thread::sleep_for(kGap);
    release(key);
    std::this_thread::sleep_for(kGap);
  }

 private:
  template <class F>
  static void load(void* library, const char* name, F& f) {
    f = reinterpret_cast<F>(dlsym(library, name));
    if (!f) throw std::runtime_error(std::string("XKeys: no ") + name);
  }
  void send(const std::string& key, bool down) {
    const unsigned long sym = keysym_(key.c_str());
    const unsigned char code = sym ? keycode_(display_, sym) : 0;
    if (!code) throw std::runtime_error("XKeys: no key for " + key);
    fake_key_(display_, code, down ? 1 : 0, 0);
    sync_(display_, 0);  // the server has it (and has routed it) when this returns
  }

  void* x11_ = nullptr;
  void* xtst_ = nullptr;
  void* display_ = nullptr;
  void* (*open_)(const char*) = nullptr;
  int (*close_)(void*) = nullptr;
  unsigned long (*keysym_)(const char*) = nullptr;
  unsigned char (*keycode_)(void*, unsigned long) = nullptr;
  int (*sync_)(void*, int) = nullptr;
  int (*query_)(void*, int*, int*, int*, int*) = nullptr;
  int (*fake_key_)(void*, unsigned int, int, unsigned long) = nullptr;
};

}  // namespace nibrig::ui::panel::testing
