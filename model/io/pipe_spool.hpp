// An input given as a pipe (`cat judgments.csv | nibrig space fit /dev/stdin`) can be read once,
// but a reader that first looks at a file's header to tell its format opens it twice: the second
// read found it empty. A pipe is therefore copied once, whole, to a private temporary file that
// every later open of the same name reads.
#pragma once

#include <cstddef>
#include <filesystem>

namespace nibrig::model::io {

// The most a pipe may carry: more than any input nibrig reads from one (the bundled catalog is
// 1.3 MB), and a bound on an endless producer.
inline constexpr std::size_t kMaxPipedBytes = std::size_t{256} << 20;

// What to open for `file`: itself, or for a pipe the copy of what it carried. Throws FormatError
// naming `file` when the pipe carries more than kMaxPipedBytes or cannot be copied. The copies are
// removed when the process ends (and by interrupt_cleanup's handler).
std::filesystem::path readable_path(const std::filesystem::path& file);

}  // namespace nibrig::model::io
