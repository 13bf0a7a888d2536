#include "model/io/bounded_read.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>

#include "model/io/format_error.hpp"
#include "model/io/job_files.hpp"
#include "model/io/pipe_spool.hpp"

namespace nibrig::model::io {

std::string byte_bound_text(std::size_t bytes) {
  if (bytes >= (std::size_t{1} << 20) && bytes % (std::size_t{1} << 20) == 0)
    return std::to_string(bytes >> 20) + " MiB";
  if (bytes >= (std::size_t{1} << 10) && bytes % (std::size_t{1} << 10) == 0)
    return std::to_string(bytes >> 10) + " KiB";
  return std::to_string(bytes) + " bytes";
}

std::string read_bounded_file(const std::filesystem::path& file, std::size_t max_bytes,
                              std::string_view kind, std::string_view largest_real) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) {
    throw FormatError(file, "", "is a folder, expected " + std::string(kind));
  }
  std::ifstream in(readable_path(file), std::ios::binary);
  if (!in) {
    const int error = errno;
    throw FormatError(file, "",
                      std::string("cannot open for reading") +
                          (error != 0 ? std::string(" (") + std::strerror(error) + ")" : ""));
  }
  note_input(file);
  std::string text;
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
    if (text.size() > max_bytes) {
      throw FormatError(file, "",
                        "larger than " + byte_bound_text(max_bytes) + ", expected " +
                            std::string(kind) + ": none is near that size (" +
                            std::string(largest_real) + "); is this the right file?");
    }
  }
  return text;
}

}  // namespace nibrig::model::io
