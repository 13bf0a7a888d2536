#include "model/io/job_files.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <mutex>
#include <string>
#include <vector>

#include "model/io/atomic_file.hpp"

namespace nibrig::model::io {
namespace {

// A file is known by its device and inode, so that a link, a hard link or another spelling of the
// same path is the same file.
struct FileId {
  dev_t device = 0;
  ino_t inode = 0;
  bool operator==(const FileId&) const = default;
};

bool identify(const std::filesystem::path& file, FileId& id) {
  struct stat info {};
  if (::stat(file.c_str(), &info) != 0 || !S_ISREG(info.st_mode)) return false;
  id = {info.st_dev, info.st_ino};
  return true;
}

struct Input {
  FileId id;
  std::filesystem::path name;
};

struct Notes {
  std::mutex mutex;
  int jobs = 0;
  std::vector<Input> inputs;
  std::vector<FileId> outputs;
};

Notes& notes() {
  static Notes instance;
  return instance;
}

}  // namespace

JobFiles::JobFiles() {
  std::lock_guard lock(notes().mutex);
  ++notes().jobs;
}

JobFiles::~JobFiles() {
  std::lock_guard lock(notes().mutex);
  if (--notes().jobs == 0) {
    notes().inputs.clear();
    notes().outputs.clear();
  }
}

void note_input(const std::filesystem::path& file) {
  FileId id;
  if (!identify(file, id)) return;  // a pipe or a device: nothing a writer could replace
  Notes& n = notes();
  std::lock_guard lock(n.mutex);
  if (n.jobs == 0) return;
  if (std::find(n.outputs.begin(), n.outputs.end(), id) != n.outputs.end()) return;
  if (std::none_of(n.inputs.begin(), n.inputs.end(), [&](const Input& i) { return i.id == id; }))
    n.inputs.push_back({id, file});
}

void note_output(const std::filesystem::path& file) {
  FileId id;
  if (!identify(file, id)) return;
  Notes& n = notes();
  std::lock_guard lock(n.mutex);
  if (n.jobs == 0) return;
  if (std::find(n.outputs.begin(), n.outputs.end(), id) == n.outputs.end()) n.outputs.push_back(id);
}

void release_input(const std::filesystem::path& file) {
  FileId id;
  if (!identify(file, id)) return;
  Notes& n = notes();
  std::lock_guard lock(n.mutex);
  n.inputs.erase(
      std::remove_if(n.inputs.begin(), n.inputs.end(), [&](const Input& i) { return i.id == id; }),
      n.inputs.end());
}

void refuse_replacing_input(const std::filesystem::path& named,
                            const std::filesystem::path& target) {
  FileId id;
  if (!identify(target, id)) return;
  std::filesystem::path input;
  {
    Notes& n = notes();
    std::lock_guard lock(n.mutex);
    const auto found =
        std::find_if(n.inputs.begin(), n.inputs.end(), [&](const Input& i) { return i.id == id; });
    if (found == n.inputs.end()) return;
    input = found->name;
  }
  const std::string through = target == named ? "" : " (through " + target.string() + ")";
  throw OutputFileError(named.string() + ": would replace " + input.string() + through +
                        ", which this command read as an input; nothing was written: name the "
                        "output elsewhere");
}

}  // namespace nibrig::model::io
