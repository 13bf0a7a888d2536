// Pen tablets through libinput: the tablets this machine has, and one tablet's pen read on a thread
// of its own. libinput's udev backend finds them (seat0, as a desktop's compositor does) and follows
// them being plugged and unplugged; libwacom names them and gives their size where the kernel's
// resolution does not. Reading needs read access to /dev/input/event* (the `input` group).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "rig/pen/pen_sample.hpp"

namespace nibrig::rig::pen {

struct TabletInfo {
  std::string name;     // the kernel's device name, e.g. "Wacom Intuos S Pen"
  // libwacom's model name when the USB id and the kernel's name tell the model apart; when several
  // models share the id and the name tells none of them, a sentence saying so (e.g. "a GAOMON or
  // Huion tablet (model not told apart by its USB id 256c:006d)"); empty when libwacom lists no
  // tablet for the id.
  std::string model;
  bool model_told_apart = false;
  std::string devnode;  // /dev/input/eventN
  double width_mm = 0.0, height_mm = 0.0;  // the active area; 0 when neither source knows it
  bool has_pressure = false, has_tilt = false;
};

// The tablets (devices with a pen) libinput sees now. Empty when there are none or when the input
// devices cannot be read (`why`, when given, says which).
std::vector<TabletInfo> list_tablets(std::string* why = nullptr);

// The tablet `name` picks: the first whose name (or libwacom model) contains it, case-insensitively;
// the first for an empty name; the one at that node for a /dev path. nullptr when none does.
const TabletInfo* match_tablet(const std::vector<TabletInfo>& tablets, const std::string& name);

struct PenEvents {
  // Every tablet-tool event (axis, tip, proximity), in order, on the reader's thread.
  std::function<void(const PenSample&)> sample;
  // The tablet went away (unplugged); no sample follows.
  std::function<void()> removed;
};

class PenInput {
 public:
  // Opens the tablet whose name (or libwacom model) contains `name`, case-insensitively; the first
  // tablet for an empty name. Throws std::invalid_argument naming the tablets there are when none
  // matches, std::runtime_error when the input devices cannot be read.
  PenInput(const std::string& name, PenEvents events);
  ~PenInput();
  PenInput(const PenInput&) = delete;
  PenInput& operator=(const PenInput&) = delete;

  const TabletInfo& tablet() const;
  bool removed() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace nibrig::rig::pen
