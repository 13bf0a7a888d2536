// Reading a whole input file into memory up to a bound, so that /dev/zero, a FIFO that never ends or
// a runaway file is refused with a FormatError instead of filling memory.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace nibrig::model::io {

// The whole content of `file`, refused past `max_bytes`. `kind` names what the file should be, as
// "a JSON file" or "an instructions text", and `largest_real` says how big a real one gets, so the
// user can tell a wrong file from a limit they might need raised.
std::string read_bounded_file(const std::filesystem::path& file, std::size_t max_bytes,
                              std::string_view kind, std::string_view largest_real);

// "256 MiB", "1 MiB", "64 KiB": a byte bound as the messages print it.
std::string byte_bound_text(std::size_t bytes);

}  // namespace nibrig::model::io
