// Writing a whole small file (catalog, triplet list, session description) so that a reader never
// sees it half written: the content goes to a temporary file beside the target, is flushed to disk,
// and is renamed over the target in one step.
#pragma once

#include <filesystem>
#include <string_view>

namespace nibrig::model::io {

// Throws std::runtime_error naming the file and the system's reason when any step fails; the
// temporary file is removed then.
void write_file_atomically(const std::filesystem::path& target, std::string_view content);

}  // namespace nibrig::model::io
