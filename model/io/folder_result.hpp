// A result that is a whole folder (the demo's report) is built beside the folder it will replace
// and swapped in only when complete, so that a run that fails or is killed halfway leaves the
// earlier result as it was, never a mix of old and new files.
#pragma once

#include <filesystem>
#include <string>

namespace nibrig::model::io {

// The list a result keeps of what it wrote: "<kind> <bytes> <modified ns> <relative path>" a line,
// kind f (file) or d (folder).
inline constexpr const char* kFolderResultFiles = ".nibrig-files";

class FolderResult {
 public:
  // `target`: the folder the user named. It may be new, empty, or an earlier result of the same
  // kind, recognised by the file `marker` in it and holding only what that result wrote, unchanged
  // (its list, kFolderResultFiles, says what): anything else there is a person's own, and replacing
  // the folder would delete it. Any other folder (or a file) is refused with a std::runtime_error
  // naming it and what is in the way, before anything is made. Work folders left beside `target`
  // by runs that were killed are removed.
  FolderResult(std::filesystem::path target, std::string marker);
  // Without commit(), the work folder and all in it are removed.
  ~FolderResult();
  FolderResult(const FolderResult&) = delete;
  FolderResult& operator=(const FolderResult&) = delete;

  // Where to build the result: an empty folder beside the target.
  const std::filesystem::path& work() const { return work_; }
  // Swaps the finished work folder in for the target in one step (the earlier result is then
  // removed). Throws std::runtime_error naming the target when the system refuses.
  void commit();

 private:
  std::filesystem::path target_, work_;
  bool committed_ = false;
};

}  // namespace nibrig::model::io
