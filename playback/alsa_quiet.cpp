#include "playback/alsa_quiet.hpp"

#include <alsa/asoundlib.h>

#include <mutex>

namespace nibrig::playback {
namespace {

void discard(const char*, int, const char*, int, const char*, ...) {}

}  // namespace

void quiet_alsa_library() {
  static std::once_flag once;
  std::call_once(once, [] { snd_lib_error_set_handler(&discard); });
}

}  // namespace nibrig::playback
