#include <sndfile.h>

#include <cmath>

#include "model/io/format_error.hpp"
#include "model/io/json_fields.hpp"
#include "model/io/rig_session.hpp"
#include "model/io/rig_session_json.hpp"
#include "model/io/job_files.hpp"

namespace nibrig::model::io {

namespace {

constexpr std::string_view kPartialSuffix = ".partial";
constexpr sf_count_t kSessionReadChunk = 1 << 16;

std::string subtype_name(int format) {
  switch (format & SF_FORMAT_SUBMASK) {
    case SF_FORMAT_PCM_S8:
      return "8-bit signed integer";
    case SF_FORMAT_PCM_U8:
      return "8-bit unsigned integer";
    case SF_FORMAT_PCM_16:
      return "16-bit integer";
    case SF_FORMAT_PCM_24:
      return "24-bit integer";
    case SF_FORMAT_PCM_32:
      return "32-bit integer";
    case SF_FORMAT_DOUBLE:
      return "64-bit float";
    case SF_FORMAT_ULAW:
      return "u-law";
    case SF_FORMAT_ALAW:
      return "A-law";
    default:
      return "encoding 0x" + [](int code) {
        static const char* hex = "0123456789abcdef";
        std::string text;
        for (int shift = 12; shift >= 0; shift -= 4) text += hex[(code >> shift) & 0xf];
        return text;
      }(format & SF_FORMAT_SUBMASK);
  }
}

// Closes the libsndfile handle on every path out, including exceptions.
struct SndFile {
  SNDFILE* handle = nullptr;
  ~SndFile() {
    if (handle != nullptr) sf_close(handle);
  }
};

std::vector<float> read_stream(const std::filesystem::path& wav, double expected_rate_hz,
                               bool complete, std::vector<std::string>& warnings) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(wav, ec)) {
    throw FormatError(wav, "", "missing: expected a mono float32 WAV stream of the session");
  }
  if (!complete && std::filesystem::file_size(wav, ec) == 0) {
    warnings.push_back(wav.string() + ": empty (the capture stopped before this stream started)");
    return {};
  }
  SF_INFO info{};
  SndFile file;
  file.handle = sf_open(wav.c_str(), SFM_READ, &info);
  if (file.handle == nullptr) {
    throw FormatError(
        wav, "", std::string("expected a WAV file (libsndfile: ") + sf_strerror(nullptr) + ")");
  }
  note_input(wav);
  const int major = info.format & SF_FORMAT_TYPEMASK;
  if (major != SF_FORMAT_WAV && major != SF_FORMAT_WAVEX && major != SF_FORMAT_RF64) {
    throw FormatError(wav, "header", "expected a WAV file, found another audio container");
  }
  if ((info.format & SF_FORMAT_SUBMASK) != SF_FORMAT_FLOAT) {
    throw FormatError(wav, "header",
                      "expected 32-bit float samples, found " + subtype_name(info.format));
  }
  if (info.channels != 1) {
    throw FormatError(wav, "header", "expected 1 channel, found " + std::to_string(info.channels));
  }
  // session.json's rates were checked to be whole numbers of hertz, so they print exactly as
  // integers.
  if (static_cast<double>(info.samplerate) != expected_rate_hz) {
    throw FormatError(wav, "header",
                      "wrong sample rate: expected " +
                          std::to_string(static_cast<long long>(expected_rate_hz)) +
                          " Hz (session.json), found " + std::to_string(info.samplerate) + " Hz");
  }
  std::vector<float> samples;
  std::vector<float> chunk(static_cast<std::size_t>(kSessionReadChunk));
  for (;;) {
    const sf_count_t got = sf_read_float(file.handle, chunk.data(), kSessionReadChunk);
    if (got <= 0) break;
    for (sf_count_t i = 0; i < got; ++i) {
      if (!std::isfinite(chunk[static_cast<std::size_t>(i)])) {
        throw FormatError(
            wav, "sample " + std::to_string(samples.size() + static_cast<std::size_t>(i)),
            "expected a finite value, found " +
                std::string(std::isnan(chunk[static_cast<std::size_t>(i)]) ? "NaN" : "infinity"));
      }
    }
    samples.insert(samples.end(), chunk.begin(), chunk.begin() + got);
  }
  if (static_cast<sf_count_t>(samples.size()) != info.frames) {
    const std::string problem = "the header announces " + std::to_string(info.frames) +
                                " frames, the file holds " + std::to_string(samples.size());
    if (complete) throw FormatError(wav, "", "truncated: " + problem);
    warnings.push_back(wav.string() + ": " + problem + " (kept what is there)");
  }
  return samples;
}

}  // namespace

RigSession read_rig_session(const std::filesystem::path& folder) {
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) {
    const std::filesystem::path partial = partial_folder_of(folder);
    if (std::filesystem::is_directory(partial, ec)) {
      throw FormatError(folder, "",
                        "no session folder; an unfinished capture left " + partial.string() +
                            " (read that path to get what it holds)");
    }
    throw FormatError(folder, "",
                      "no session folder (expected a folder with session.json and WAV streams)");
  }
  RigSession session;
  session.folder = folder;
  std::filesystem::path name = folder.lexically_normal();
  if (name.filename().empty()) name = name.parent_path();
  const std::string leaf = name.filename().string();
  session.complete = !(leaf.size() > kPartialSuffix.size() &&
                       leaf.compare(leaf.size() - kPartialSuffix.size(), kPartialSuffix.size(),
                                    kPartialSuffix) == 0);

  const std::filesystem::path json_file = folder / kSessionJson;
  if (!std::filesystem::exists(json_file, ec)) {
    throw FormatError(json_file, "", "missing: expected the session description (session.json)");
  }
  session_json::Parsed parsed =
      session_json::from_json(json_fields::parse_file(json_file), json_file);
  session.info = std::move(parsed.info);
  if (session.complete && !parsed.frames) {
    throw FormatError(json_file, json_fields::place("frames"),
                      "missing field (a finished session records its frame counts)");
  }

  const char* files[] = {kAccelerationWav, kSpeedWav, kNormalForceWav, kTangentialForceWav};
  std::vector<float>* targets[] = {&session.acceleration, &session.speed_m_s,
                                   &session.normal_force_N, &session.tangential_force_N};
  for (std::size_t k = 0; k < session_json::kStreams.size(); ++k) {
    const std::filesystem::path wav = folder / files[k];
    *targets[k] = read_stream(wav, session_json::rate_of(session.info, k), session.complete,
                              session.warnings);
    if (parsed.frames && static_cast<std::int64_t>(targets[k]->size()) != (*parsed.frames)[k]) {
      throw FormatError(wav, "",
                        "expected " + std::to_string((*parsed.frames)[k]) +
                            " frames (session.json), found " + std::to_string(targets[k]->size()));
    }
  }
  return session;
}

}  // namespace nibrig::model::io
