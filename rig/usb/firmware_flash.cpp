#include "rig/usb/firmware_flash.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <thread>
#include <vector>

#include "model/io/bundled_assets.hpp"
#include "rig/usb/usb_rig_controller.hpp"

#ifndef NIBRIG_FIRMWARE_HEX_DEFAULT
#define NIBRIG_FIRMWARE_HEX_DEFAULT ""
#endif

namespace nibrig::rig::usb {
namespace {

constexpr auto kFlashPollPeriod = std::chrono::milliseconds(100);

std::string flash_seconds(std::chrono::milliseconds wait) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f s", static_cast<double>(wait.count()) / 1000.0);
  return text;
}

std::string known_bootloaders() {
  std::string text;
  char id[16];
  for (const auto& b : kCaterinaBootloaders) {
    std::snprintf(id, sizeof id, "%04x:%04x", static_cast<unsigned>(b.vendor), static_cast<unsigned>(b.product));
    text += (text.empty() ? "" : ", ") + std::string(id);
  }
  return text;
}

SerialPort wait_for_bootloader_port(std::chrono::milliseconds wait) {
  const auto end = std::chrono::steady_clock::now() + wait;
  for (;;) {
    const auto found = bootloader_ports();
    if (!found.empty()) return found.front();
    if (std::chrono::steady_clock::now() >= end) break;
    std::this_thread::sleep_for(kFlashPollPeriod);
  }
  std::string others;
  for (const auto& p : usb_serial_ports()) others += (others.empty() ? "" : ", ") + describe(p);
  throw FirmwareFlashError("no bootloader's serial port (USB " + known_bootloaders() + ") appeared within " +
                           flash_seconds(wait) + "; USB serial ports now: " + (others.empty() ? "none" : others) +
                           ". Press the board's reset button and run `nibrig rig flash --port /dev/ttyACMn` "
                           "within the bootloader's 8 s");
}

RigControllerInfo wait_for_controller(const std::string& serial, std::chrono::milliseconds wait) {
  const auto end = std::chrono::steady_clock::now() + wait;
  std::vector<RigControllerInfo> found;
  for (;;) {
    found = list_rig_controllers();
    for (const auto& c : found) {
      if (c.problem.empty() && (serial.empty() || c.serial == serial)) return c;
    }
    if (std::chrono::steady_clock::now() >= end) break;
    std::this_thread::sleep_for(kFlashPollPeriod);
  }
  throw FirmwareFlashError("avrdude wrote the firmware, but " + missing_message(serial, found) + " within " +
                           flash_seconds(wait) + " after the upload: unplug the board and plug it in again, "
                           "then `nibrig rig devices`");
}

}  // namespace

std::filesystem::path find_firmware_hex(const std::optional<std::filesystem::path>& given) {
  namespace fs = std::filesystem;
  if (given) {
    if (!fs::is_regular_file(*given)) throw FirmwareFlashError("--hex " + given->string() + ": no such file");
    return *given;
  }
  if (const char* env = std::getenv("NIBRIG_FIRMWARE_HEX"); env != nullptr && *env != '\0') {
    if (!fs::is_regular_file(env)) {
      throw FirmwareFlashError(std::string("$NIBRIG_FIRMWARE_HEX=") + env + ": no such file");
    }
    return env;
  }
  // An installed nibrig's (cmake --install of a tree that built the firmware).
  if (const auto share = model::io::installed_share_dir(); !share.empty()) {
    const auto installed = share / "firmware" / "nibrig-rig.hex";
    if (fs::is_regular_file(installed)) return installed;
  }
  const fs::path built = NIBRIG_FIRMWARE_HEX_DEFAULT;
  if (built.empty() || !fs::is_regular_file(built)) {
    throw FirmwareFlashError("no firmware to flash: " + (built.empty() ? std::string("this build has no firmware path")
                                                                       : built.string() + " does not exist") +
                             ". Build it with `cmake -DNIBRIG_BUILD_FIRMWARE=ON` (Debian's gcc-avr and avr-libc), "
                             "or give --hex FILE or $NIBRIG_FIRMWARE_HEX");
  }
  return built;
}

std::string run_avrdude(const std::string& program, const std::string& port, const std::filesystem::path& hex) {
  const std::string memory = "flash:w:" + hex.string() + ":i";
  std::vector<std::string> args = {program, "-p", "atmega32u4", "-c", "avr109", "-P", port,
                                   "-b", "57600", "-D", "-U", memory};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) throw FirmwareFlashError(std::string("cannot start avrdude: pipe: ") + std::strerror(errno));
  const pid_t pid = fork();
  if (pid < 0) {
    close(pipe_fds[0]);
    close(pipe_fds[1]);
    throw FirmwareFlashError(std::string("cannot start avrdude: fork: ") + std::strerror(errno));
  }
  if (pid == 0) {  // the child: only async-signal-safe calls until exec
    dup2(pipe_fds[1], STDOUT_FILENO);
    dup2(pipe_fds[1], STDERR_FILENO);
    close(pipe_fds[0]);
    close(pipe_fds[1]);
    execvp(argv[0], argv.data());
    static const char kExecFailed[] = "exec failed\n";
    [[maybe_unused]] const auto written = write(STDERR_FILENO, kExecFailed, sizeof kExecFailed - 1);
    _exit(127);
  }
  close(pipe_fds[1]);
  std::string output;
  char buffer[4096];
  for (;;) {
    const ssize_t n = read(pipe_fds[0], buffer, sizeof buffer);
    if (n > 0) {
      output.append(buffer, static_cast<std::size_t>(n));
    } else if (n == 0 || errno != EINTR) {
      break;
    }
  }
  close(pipe_fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 127 && output.find("exec failed") != std::string::npos) {
    throw FirmwareFlashError("cannot run '" + program + "': is avrdude installed? (Debian: apt-get install avrdude)");
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    const std::string how = WIFEXITED(status) ? "exit code " + std::to_string(WEXITSTATUS(status))
                                              : "signal " + std::to_string(WTERMSIG(status));
    throw FirmwareFlashError("avrdude failed (" + how + ") writing " + hex.string() + " through " + port + ":\n" +
                             output);
  }
  return output;
}

FirmwareFlashResult flash_firmware(const FirmwareFlashOptions& options, const FlashProgress& progress) {
  FirmwareFlashResult result;
  result.hex = find_firmware_hex(options.hex);
  std::string serial = options.serial;
  if (options.port) {
    result.port.device = *options.port;
    for (const auto& p : usb_serial_ports()) {
      if (p.device == *options.port) result.port = p;
    }
  } else {
    {
      UsbRigController::Options o;
      o.serial = options.serial;
      UsbRigController rig(o);
      serial = rig.identity().serial;
      progress("asking the rig controller " + serial + " (firmware " + rig.identity().firmware +
               ") into its bootloader");
      rig.enter_bootloader();
    }
    progress("waiting up to " + flash_seconds(options.port_wait) + " for the bootloader's serial port");
    result.port = wait_for_bootloader_port(options.port_wait);
  }
  progress("writing " + result.hex.string() + " through " + describe(result.port) + " with avrdude");
  result.avrdude_output = run_avrdude(options.avrdude, result.port.device, result.hex);
  progress("waiting up to " + flash_seconds(options.return_wait) + " for the rig controller to come back");
  result.controller = wait_for_controller(serial, options.return_wait);
  return result;
}

}  // namespace nibrig::rig::usb
