#include <fcntl.h>
#include <sndfile.h>
#include <stdio.h>  // renameat2

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <stdexcept>

#include "model/io/atomic_file.hpp"
#include "model/io/rig_session.hpp"
#include "model/io/utc_time.hpp"
#include "model/io/rig_session_json.hpp"

namespace nibrig::model::io {

namespace {

std::string dump_json(const nlohmann::json& json) {
  try {
    return json.dump(2) + "\n";
  } catch (const nlohmann::json::type_error& error) {
    throw std::invalid_argument(std::string("session info holds text that is not valid UTF-8 (") +
                                error.what() + ")");
  }
}

// Renames without ever replacing an existing target (a plain rename(2) silently replaces an empty
// folder).
void rename_no_replace(const std::filesystem::path& from, const std::filesystem::path& to) {
  if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0) return;
  const int error = errno;
  if (error == EEXIST || error == ENOTEMPTY) {
    throw std::runtime_error(to.string() +
                             ": cannot finish the session, the folder already exists; "
                             "the recording stays in " +
                             from.string());
  }
  throw std::runtime_error(to.string() + ": cannot finish the session (" + std::strerror(error) +
                           "); the recording stays in " + from.string());
}

}  // namespace

struct RigSessionWriter::Stream {
  std::filesystem::path path;
  const char* name = "";
  SNDFILE* file = nullptr;
  std::int64_t frames = 0;
};

namespace {
std::filesystem::path without_trailing_separator(const std::filesystem::path& folder) {
  std::filesystem::path normal = folder.lexically_normal();
  if (normal.filename().empty()) normal = normal.parent_path();  // "x/" names the folder x
  return normal;
}
}  // namespace

std::filesystem::path partial_folder_of(const std::filesystem::path& folder) {
  std::filesystem::path partial = without_trailing_separator(folder);
  partial += ".partial";
  return partial;
}

RigSessionWriter::RigSessionWriter(std::filesystem::path folder, RigSessionInfo info)
    : folder_(without_trailing_separator(folder)),
      partial_(partial_folder_of(folder_)),
      info_(std::move(info)) {
  if (auto problem = session_json::check(info_)) {
    throw std::invalid_argument(std::string(kSessionJson) + " field '" + problem->field +
                                "': " + problem->what);
  }
  if (info_.created_utc.empty()) info_.created_utc = now_utc_iso8601();
  const std::string description = dump_json(session_json::to_json(info_, nullptr));

  std::error_code ec;
  if (std::filesystem::exists(folder_, ec)) {
    throw std::runtime_error(folder_.string() + ": a session already exists there");
  }
  if (!partial_.parent_path().empty())
    std::filesystem::create_directories(partial_.parent_path(), ec);
  if (!std::filesystem::create_directory(partial_, ec)) {
    throw std::runtime_error(
        partial_.string() +
        (ec ? ": cannot create the session folder (" + ec.message() + ")"
            : ": a partial session already exists (an interrupted capture?); measure it with "
              "`nibrig measure " + partial_.string() + "` or remove it"));
  }
  try {
    write_file_atomically(partial_ / kSessionJson, description);
    const char* files[] = {kAccelerationWav, kSpeedWav, kNormalForceWav, kTangentialForceWav};
    for (std::size_t k = 0; k < session_json::kStreams.size(); ++k) {
      auto stream = std::make_unique<Stream>();
      stream->path = partial_ / files[k];
      stream->name = session_json::kStreams[k];
      SF_INFO format{};
      format.samplerate = static_cast<int>(session_json::rate_of(info_, k));
      format.channels = 1;
      format.format = SF_FORMAT_WAV | SF_FORMAT_FLOAT;
      stream->file = sf_open(stream->path.c_str(), SFM_WRITE, &format);
      if (stream->file == nullptr) {
        throw std::runtime_error(stream->path.string() + ": cannot create (" +
                                 sf_strerror(nullptr) + ")");
      }
      // Rewrite the header after every write, so the file is a valid WAV of everything written so
      // far whenever the process dies.
      sf_command(stream->file, SFC_SET_UPDATE_HEADER_AUTO, nullptr, SF_TRUE);
      streams_.push_back(std::move(stream));
    }
  } catch (...) {
    close_streams();
    std::filesystem::remove_all(partial_, ec);
    throw;
  }
}

RigSessionWriter::~RigSessionWriter() { close_streams(); }

void RigSessionWriter::discard() noexcept {
  if (finished_) return;
  close_streams();
  std::error_code ignored;
  std::filesystem::remove_all(partial_, ignored);
}

void RigSessionWriter::close_streams() noexcept {
  for (auto& stream : streams_) {
    if (stream->file != nullptr) {
      sf_close(stream->file);
      stream->file = nullptr;
    }
  }
}

void RigSessionWriter::append(Stream& stream, std::span<const float> samples) {
  if (finished_) {
    throw std::logic_error(partial_.string() + ": append to " + stream.name + " after finish()");
  }
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (!std::isfinite(samples[i])) {
      throw std::invalid_argument(stream.path.string() + ": sample " + std::to_string(i) +
                                  " of the block is not finite; block not written");
    }
  }
  if (samples.empty()) return;
  const auto count = static_cast<sf_count_t>(samples.size());
  const sf_count_t written = sf_write_float(stream.file, samples.data(), count);
  if (written > 0) stream.frames += written;
  if (written != count) {
    throw std::runtime_error(stream.path.string() + ": write failed after " +
                             std::to_string(stream.frames) + " frames (" +
                             sf_strerror(stream.file) + ")");
  }
}

void RigSessionWriter::append_acceleration(std::span<const float> samples) {
  append(*streams_[0], samples);
}
void RigSessionWriter::append_speed(std::span<const float> samples_m_s) {
  append(*streams_[1], samples_m_s);
}
void RigSessionWriter::append_normal_force(std::span<const float> samples_N) {
  append(*streams_[2], samples_N);
}
void RigSessionWriter::append_tangential_force(std::span<const float> samples_N) {
  append(*streams_[3], samples_N);
}

void RigSessionWriter::update_capture(const CaptureRecord& record) {
  if (finished_) throw std::logic_error(partial_.string() + ": update_capture after finish()");
  info_.capture = record;
  write_file_atomically(partial_ / kSessionJson, dump_json(session_json::to_json(info_, nullptr)));
}

void RigSessionWriter::finish() {
  if (finished_) throw std::logic_error(folder_.string() + ": finish() called twice");
  finished_ = true;
  std::array<std::int64_t, 4> frames{};
  std::string failure;
  for (std::size_t k = 0; k < streams_.size(); ++k) {
    frames[k] = streams_[k]->frames;
    sf_write_sync(streams_[k]->file);
    if (sf_close(streams_[k]->file) != 0 && failure.empty()) {
      failure = streams_[k]->path.string() + ": cannot close";
    }
    streams_[k]->file = nullptr;
  }
  if (!failure.empty())
    throw std::runtime_error(failure + "; the recording stays in " + partial_.string());
  write_file_atomically(partial_ / kSessionJson, dump_json(session_json::to_json(info_, &frames)));
  rename_no_replace(partial_, folder_);
}

}  // namespace nibrig::model::io
