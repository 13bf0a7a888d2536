#include "rig/pen/pen_input.hpp"

#include <fcntl.h>
#include <libinput.h>
#include <libudev.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <atomic>
#include <cerrno>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <thread>

#include "rig/pen/tablet_model_name.hpp"

namespace nibrig::rig::pen {
namespace {

// What libinput said while opening devices: the reason a list comes back empty.
struct PenLog {
  std::vector<std::string> lines;
};

int pen_open_restricted(const char* path, int flags, void*) {
  const int fd = ::open(path, flags);
  return fd < 0 ? -errno : fd;
}

void pen_close_restricted(int fd, void*) { ::close(fd); }

const libinput_interface kPenInterface = {pen_open_restricted, pen_close_restricted};

void pen_log_handler(libinput* li, libinput_log_priority, const char* format, va_list args) {
  auto* log = static_cast<PenLog*>(libinput_get_user_data(li));
  char line[512];
  std::vsnprintf(line, sizeof line, format, args);
  std::string text(line);
  while (!text.empty() && text.back() == '\n') text.pop_back();
  if (log && log->lines.size() < 64) log->lines.push_back(text);
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// The input device's `capabilities/abs` bitmask (hex words, most significant first) has the
// pressure and tilt axes before any pen comes near, which libinput only tells per tool.
void read_axes(libinput_device* device, TabletInfo& info) {
  udev_device* event = libinput_device_get_udev_device(device);
  if (!event) return;
  if (udev_device* input = udev_device_get_parent_with_subsystem_devtype(event, "input", nullptr)) {
    if (const char* abs = udev_device_get_sysattr_value(input, "capabilities/abs")) {
      const std::string words(abs);
      const auto last = words.find_last_of(' ');
      const unsigned long low = std::strtoul(words.c_str() + (last == std::string::npos ? 0 : last + 1), nullptr, 16);
      info.has_pressure = (low >> 24) & 1u;                       // ABS_PRESSURE
      info.has_tilt = ((low >> 26) & 1u) && ((low >> 27) & 1u);  // ABS_TILT_X, ABS_TILT_Y
    }
  }
  udev_device_unref(event);
}

TabletInfo describe(libinput_device* device) {
  TabletInfo info;
  info.name = libinput_device_get_name(device);
  if (udev_device* event = libinput_device_get_udev_device(device)) {
    if (const char* node = udev_device_get_devnode(event)) info.devnode = node;
    udev_device_unref(event);
  }
  double width = 0, height = 0;
  if (libinput_device_get_size(device, &width, &height) == 0) {
    info.width_mm = width;
    info.height_mm = height;
  }
  // libwacom names the model from the USB id and the kernel's name together (tablet_model_name.hpp:
  // one id may be many models); its sizes are whole inches, so the kernel's resolution (above) is
  // preferred when there is one.
  const auto vendor = static_cast<std::uint16_t>(libinput_device_get_id_vendor(device));
  const auto product = static_cast<std::uint16_t>(libinput_device_get_id_product(device));
  const TabletModelName model = name_tablet_model(libwacom_usb_matches(vendor, product), info.name, vendor, product);
  info.model = model.model;
  info.model_told_apart = model.told_apart;
  if ((info.width_mm <= 0 || info.height_mm <= 0) && model.told_apart) {
    info.width_mm = model.width_mm;
    info.height_mm = model.height_mm;
  }
  read_axes(device, info);
  return info;
}

bool is_tablet(libinput_device* device) {
  return libinput_device_has_capability(device, LIBINPUT_DEVICE_CAP_TABLET_TOOL) != 0;
}

// libinput averages a tablet's last four positions (its "tablet smoothing", on for every tablet but
// AES ones), which delays the pen by one and a half reports before nibrig sees it; the speed's own
// smoothing then adds its one report. For nibrig's contexts only, libinput reads the system's quirks
// plus one that turns that averaging off (AttrTabletSmoothing=0): the desktop keeps its own.
void use_unsmoothed_quirks() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (std::getenv("LIBINPUT_QUIRKS_DIR")) return;  // someone chose the quirks already
    namespace fs = std::filesystem;
    std::error_code error;
    const char* runtime = std::getenv("XDG_RUNTIME_DIR");
    const fs::path folder = fs::path(runtime && *runtime ? runtime : fs::temp_directory_path(error).string()) /
                            ("nibrig-libinput-quirks-" + std::to_string(::getuid()));
    fs::create_directories(folder, error);
    for (const auto& entry : fs::directory_iterator("/usr/share/libinput", error)) {
      if (entry.path().extension() != ".quirks") continue;
      fs::remove(folder / entry.path().filename(), error);
      fs::create_symlink(entry.path(), folder / entry.path().filename(), error);
    }
    const fs::path local = "/etc/libinput/local-overrides.quirks";
    fs::remove(folder / "98-local-overrides.quirks", error);
    if (fs::exists(local, error)) fs::create_symlink(local, folder / "98-local-overrides.quirks", error);
    std::ofstream(folder / "99-nibrig-pen.quirks")
        << "[nibrig: pen positions as the tablet reports them]\nMatchUdevType=tablet\nAttrTabletSmoothing=0\n";
    if (fs::exists(folder / "99-nibrig-pen.quirks", error)) ::setenv("LIBINPUT_QUIRKS_DIR", folder.c_str(), 0);
  });
}

bool is_device_node(const std::string& name) { return name.rfind("/dev/", 0) == 0; }

// A context on seat0 through udev, or on one node through the path backend when the name is a
// /dev path (a machine without a seat, or a tablet udev does not tag).
libinput* open_context(const std::string& name, PenLog& log, udev*& u) {
  use_unsmoothed_quirks();
  libinput* li = nullptr;
  if (is_device_node(name)) {
    li = libinput_path_create_context(&kPenInterface, &log);
  } else {
    u = udev_new();
    if (!u) throw std::runtime_error("pen tablets: cannot reach udev");
    li = libinput_udev_create_context(&kPenInterface, &log, u);
  }
  if (!li) throw std::runtime_error("pen tablets: libinput could not start");
  libinput_log_set_handler(li, pen_log_handler);
  libinput_log_set_priority(li, LIBINPUT_LOG_PRIORITY_INFO);
  if (is_device_node(name)) {
    if (!libinput_path_add_device(li, name.c_str())) {
      std::string why = log.lines.empty() ? "not an input device libinput can use" : log.lines.back();
      libinput_unref(li);
      throw std::runtime_error("pen tablet " + name + ": " + why);
    }
  } else if (libinput_udev_assign_seat(li, "seat0") != 0) {
    libinput_unref(li);
    udev_unref(u);
    u = nullptr;
    throw std::runtime_error("pen tablets: libinput could not read seat0's input devices");
  }
  return li;
}

// Why nothing could be opened, from libinput's own lines: the group a user needs, named.
std::string unreadable(const PenLog& log) {
  for (const auto& line : log.lines) {
    if (line.find("Permission denied") != std::string::npos) {
      return line + " (reading tablets needs read access to /dev/input: join the `input` group)";
    }
  }
  return {};
}

std::vector<libinput_device*> added_tablets(libinput* li) {
  std::vector<libinput_device*> found;
  libinput_dispatch(li);
  while (libinput_event* event = libinput_get_event(li)) {
    if (libinput_event_get_type(event) == LIBINPUT_EVENT_DEVICE_ADDED) {
      libinput_device* device = libinput_event_get_device(event);
      if (is_tablet(device)) found.push_back(libinput_device_ref(device));
    }
    libinput_event_destroy(event);
  }
  return found;
}

}  // namespace

const TabletInfo* match_tablet(const std::vector<TabletInfo>& tablets, const std::string& name) {
  const std::string wanted = lower(name);
  for (const auto& t : tablets) {
    if (wanted.empty() || (is_device_node(name) && t.devnode == name) || lower(t.name).find(wanted) != std::string::npos ||
        (!t.model.empty() && lower(t.model).find(wanted) != std::string::npos)) {
      return &t;
    }
  }
  return nullptr;
}

std::vector<TabletInfo> list_tablets(std::string* why) {
  PenLog log;
  udev* u = nullptr;
  libinput* li = nullptr;
  try {
    li = open_context("", log, u);
  } catch (const std::exception& e) {
    if (why) *why = e.what();
    return {};
  }
  std::vector<TabletInfo> tablets;
  for (libinput_device* device : added_tablets(li)) {
    tablets.push_back(describe(device));
    libinput_device_unref(device);
  }
  if (why && tablets.empty()) *why = unreadable(log);
  libinput_unref(li);
  udev_unref(u);
  return tablets;
}

struct PenInput::Impl {
  PenEvents events;
  PenLog log;
  udev* u = nullptr;
  libinput* li = nullptr;
  libinput_device* device = nullptr;
  TabletInfo info;
  int stop_fd = -1;
  std::atomic<bool> removed{false};
  std::thread thread;

  void run();
  void handle(libinput_event* event);
  void emit_tool(libinput_event_tablet_tool* tool);
  void end_with_removal();
  bool tip_down = false, in_proximity = false;
  double last_time_s = 0, last_x_m = 0, last_y_m = 0;
};

PenInput::PenInput(const std::string& name, PenEvents events) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.events = std::move(events);
  m.li = open_context(name, m.log, m.u);
  std::vector<libinput_device*> tablets = added_tablets(m.li);
  std::vector<TabletInfo> infos;
  for (libinput_device* device : tablets) infos.push_back(describe(device));
  const TabletInfo* chosen = match_tablet(infos, name);
  std::string names;
  for (std::size_t i = 0; i < tablets.size(); ++i) {
    if (chosen == &infos[i]) {
      m.device = tablets[i];
      m.info = infos[i];
    } else {
      libinput_device_unref(tablets[i]);
    }
    names += (names.empty() ? "" : ", ") + ("\"" + infos[i].name + "\"");
  }
  if (!m.device) {
    const std::string why = unreadable(m.log);
    libinput_unref(m.li);
    if (m.u) udev_unref(m.u);
    if (!why.empty()) throw std::runtime_error("pen tablets: " + why);
    if (names.empty()) {
      throw std::invalid_argument("no pen tablet found (is one plugged in?)");
    }
    throw std::invalid_argument("pen tablet \"" + name + "\": none of that name; there are " + names);
  }
  m.stop_fd = eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK);
  m.thread = std::thread([&m] { m.run(); });
}

PenInput::~PenInput() {
  Impl& m = *impl_;
  const std::uint64_t one = 1;
  if (::write(m.stop_fd, &one, sizeof one) < 0) {
    // The eventfd cannot be full after one write; nothing else to do but join.
  }
  if (m.thread.joinable()) m.thread.join();
  ::close(m.stop_fd);
  if (m.device) libinput_device_unref(m.device);
  libinput_unref(m.li);
  if (m.u) udev_unref(m.u);
}

const TabletInfo& PenInput::tablet() const { return impl_->info; }
bool PenInput::removed() const { return impl_->removed.load(std::memory_order_acquire); }

void PenInput::Impl::run() {
  pollfd fds[2] = {{libinput_get_fd(li), POLLIN, 0}, {stop_fd, POLLIN, 0}};
  while (true) {
    const int ready = ::poll(fds, 2, -1);
    if (ready < 0 && errno == EINTR) continue;
    if (ready > 0 && fds[1].revents == POLLIN) return;  // asked to stop
    if (ready < 0 || (fds[0].revents & (POLLERR | POLLNVAL)) || fds[1].revents) {
      // The reader cannot go on (its descriptors failed): to its owner that is the tablet gone, so
      // that a stroke ends and a face says so instead of waiting for reports that never come.
      end_with_removal();
      return;
    }
    libinput_dispatch(li);
    while (libinput_event* event = libinput_get_event(li)) {
      handle(event);
      libinput_event_destroy(event);
    }
  }
}

void PenInput::Impl::end_with_removal() {
  if (removed.load(std::memory_order_acquire)) return;
  if (tip_down || in_proximity) {
    PenSample last;
    last.time_s = last_time_s;
    last.x_m = last_x_m;
    last.y_m = last_y_m;
    tip_down = in_proximity = false;
    if (events.sample) events.sample(last);
  }
  removed.store(true, std::memory_order_release);
  if (events.removed) events.removed();
}

void PenInput::Impl::handle(libinput_event* event) {
  if (libinput_event_get_device(event) != device) return;
  switch (libinput_event_get_type(event)) {
    case LIBINPUT_EVENT_DEVICE_REMOVED:
      // A stroke in progress ends here: the last sample says the tip is up and the pen gone.
      end_with_removal();
      break;
    case LIBINPUT_EVENT_TABLET_TOOL_PROXIMITY: {
      auto* tool = libinput_event_get_tablet_tool_event(event);
      in_proximity = libinput_event_tablet_tool_get_proximity_state(tool) == LIBINPUT_TABLET_TOOL_PROXIMITY_STATE_IN;
      if (!in_proximity) tip_down = false;
      emit_tool(tool);
      break;
    }
    case LIBINPUT_EVENT_TABLET_TOOL_TIP: {
      auto* tool = libinput_event_get_tablet_tool_event(event);
      tip_down = libinput_event_tablet_tool_get_tip_state(tool) == LIBINPUT_TABLET_TOOL_TIP_DOWN;
      emit_tool(tool);
      break;
    }
    case LIBINPUT_EVENT_TABLET_TOOL_AXIS:
      emit_tool(libinput_event_get_tablet_tool_event(event));
      break;
    default:
      break;
  }
}

void PenInput::Impl::emit_tool(libinput_event_tablet_tool* tool) {
  PenSample s;
  s.time_s = 1e-6 * static_cast<double>(libinput_event_tablet_tool_get_time_usec(tool));
  // libinput gives millimetres from the tablet's top-left corner when the tablet has a resolution.
  s.x_m = 1e-3 * libinput_event_tablet_tool_get_x(tool);
  s.y_m = 1e-3 * libinput_event_tablet_tool_get_y(tool);
  libinput_tablet_tool* t = libinput_event_tablet_tool_get_tool(tool);
  if (libinput_tablet_tool_has_pressure(t)) s.pressure = libinput_event_tablet_tool_get_pressure(tool);
  if (libinput_tablet_tool_has_tilt(t)) {
    s.tilt_x_deg = libinput_event_tablet_tool_get_tilt_x(tool);
    s.tilt_y_deg = libinput_event_tablet_tool_get_tilt_y(tool);
  }
  s.tip_down = tip_down;
  s.in_proximity = in_proximity;
  last_time_s = s.time_s;
  last_x_m = s.x_m;
  last_y_m = s.y_m;
  if (events.sample) events.sample(s);
}

}  // namespace nibrig::rig::pen
