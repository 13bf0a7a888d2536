// alsa-lib prints every failed lookup of a card straight to stderr (a dozen lines per probe on a
// machine without a sound card), before RtAudio says anything. The reason an API is unavailable is
// reported by audio_devices instead, so the library's own printing is switched off.
#pragma once

namespace nibrig::playback {

// Idempotent and thread-safe; call before RtAudio touches ALSA.
void quiet_alsa_library();

}  // namespace nibrig::playback
