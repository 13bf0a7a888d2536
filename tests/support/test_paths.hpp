// Where tests find the shared real data and a scratch folder of their own.
#pragma once

#include <filesystem>
#include <string>

namespace nibrig::test {

// ../shared/data beside the repository, or $NIBRIG_SHARED_DATA. Tests of the science use real
// recordings; a missing folder is a failure, not a skip.
std::filesystem::path shared_data();

// A fresh, empty folder under the build tree for one test process (removed and recreated on each
// call with the same name in the same process).
std::filesystem::path scratch_dir(const std::string& name);

// The repository's assets/ folder.
std::filesystem::path assets_dir();

}  // namespace nibrig::test
