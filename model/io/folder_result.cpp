#include "model/io/folder_result.hpp"

#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <string>
#include <system_error>
#include <vector>

#include "model/io/interrupt_cleanup.hpp"

namespace nibrig::model::io {
namespace {

constexpr std::string_view kWorkInfix = ".partial-";

std::string work_prefix(const std::filesystem::path& target) {
  return "." + target.filename().string() + std::string(kWorkInfix);
}

// Work folders of processes that no longer run: what a killed run left behind.
void remove_abandoned_work(const std::filesystem::path& target) {
  const std::filesystem::path parent = target.parent_path().empty() ? "." : target.parent_path();
  const std::string prefix = work_prefix(target);
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(parent, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const std::string pid_text = name.substr(prefix.size());
    if (pid_text.empty() || pid_text.find_first_not_of("0123456789") != std::string::npos) continue;
    const long pid = std::stol(pid_text);
    if (pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH)
      std::filesystem::remove_all(entry.path(), ec);
  }
}

// One line of kFolderResultFiles for every file and folder below `root`, sorted.
std::set<std::string> listing(const std::filesystem::path& root) {
  std::set<std::string> lines;
  std::error_code ec;
  for (auto it = std::filesystem::recursive_directory_iterator(root, ec);
       !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec)) {
    const std::string relative = it->path().lexically_relative(root).string();
    if (relative == kFolderResultFiles) continue;
    struct stat info {};
    if (::lstat(it->path().c_str(), &info) != 0) continue;
    std::ostringstream line;
    if (S_ISDIR(info.st_mode))
      line << "d 0 0 " << relative;
    else
      line << "f " << info.st_size << ' '
           << static_cast<long long>(info.st_mtim.tv_sec) * 1000000000LL + info.st_mtim.tv_nsec << ' '
           << relative;
    lines.insert(line.str());
  }
  return lines;
}

std::set<std::string> recorded_listing(const std::filesystem::path& target) {
  std::set<std::string> lines;
  std::ifstream in(target / kFolderResultFiles);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) lines.insert(line);
  return lines;
}

// The name a listing line ends with: after the third space.
std::string listed_name(const std::string& line) {
  std::size_t at = 0;
  for (int spaces = 0; spaces < 3 && at != std::string::npos; ++spaces) at = line.find(' ', at + 1);
  return at == std::string::npos ? line : line.substr(at + 1);
}

// Refuses an earlier result that holds anything it did not write, or something changed since.
void refuse_foreign_content(const std::filesystem::path& target, const std::string& marker) {
  std::error_code ec;
  if (std::filesystem::is_empty(target, ec)) return;
  if (!std::filesystem::exists(target / marker))
    throw std::runtime_error(target.string() + ": holds files but no " + marker +
                             ", so it is not an earlier report to replace; name a new or "
                             "empty folder");
  const auto recorded = recorded_listing(target);
  if (recorded.empty())
    throw std::runtime_error(target.string() + ": has no list of what the earlier report there wrote (" +
                             kFolderResultFiles + "), so replacing it could delete files of your own; "
                             "name a new or empty folder, or remove this one");
  std::vector<std::string> foreign;
  for (const auto& line : listing(target))
    if (recorded.count(line) == 0) foreign.push_back(listed_name(line));
  if (foreign.empty()) return;
  std::string names;
  for (std::size_t i = 0; i < foreign.size() && i < 4; ++i) names += (i ? ", " : "") + foreign[i];
  if (foreign.size() > 4) names += " and " + std::to_string(foreign.size() - 4) + " more";
  throw std::runtime_error(target.string() + ": holds " + names +
                           ", not written by the earlier report there or changed since; replacing "
                           "the report would delete them: move them out or name another folder");
}

}  // namespace

FolderResult::FolderResult(std::filesystem::path target, std::string marker)
    : target_(std::move(target)) {
  if (target_.filename().empty()) target_ = target_.parent_path();  // "out/" names "out"
  std::error_code ec;
  const auto status = std::filesystem::symlink_status(target_, ec);
  if (std::filesystem::exists(status)) {
    if (!std::filesystem::is_directory(status))
      throw std::runtime_error(target_.string() + ": is not a folder (expected a new folder or an "
                                                  "earlier report to replace)");
    refuse_foreign_content(target_, marker);
  }
  remove_abandoned_work(target_);
  work_ = target_.parent_path() / (work_prefix(target_) + std::to_string(::getpid()));
  std::filesystem::remove_all(work_, ec);
  std::filesystem::create_directories(work_, ec);
  if (ec)
    throw std::runtime_error(work_.string() + ": cannot make the folder to build the report in (" +
                             ec.message() + ")");
  track_temporary(work_);
}

FolderResult::~FolderResult() {
  if (committed_) return;
  std::error_code ec;
  std::filesystem::remove_all(work_, ec);
  untrack_temporary(work_);
}

void FolderResult::commit() {
  std::error_code ec;
  {
    std::ofstream list(work_ / kFolderResultFiles);
    for (const auto& line : listing(work_)) list << line << '\n';
    if (!list.flush())
      throw std::runtime_error(work_.string() + ": cannot write " + kFolderResultFiles);
  }
  if (!std::filesystem::exists(std::filesystem::symlink_status(target_, ec))) {
    std::filesystem::rename(work_, target_, ec);
    if (ec)
      throw std::runtime_error(target_.string() + ": cannot move the finished report into place (" +
                               ec.message() + ")");
  } else {
    // One step: a reader sees the old report or the new one, never neither.
    if (::renameat2(AT_FDCWD, work_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) == 0) {
      std::filesystem::remove_all(work_, ec);  // now the earlier report
    } else if (errno == EINVAL || errno == ENOSYS) {
      // A file system without the exchange: two renames, the earlier report moved aside first
      // and removed only once the new one is in place.
      const std::filesystem::path aside =
          target_.parent_path() / ("." + target_.filename().string() + ".old-" +
                                   std::to_string(::getpid()));
      std::filesystem::rename(target_, aside, ec);
      if (!ec) {
        std::filesystem::rename(work_, target_, ec);
        std::error_code restored;
        if (ec) std::filesystem::rename(aside, target_, restored);  // the earlier report back
      }
      if (ec)
        throw std::runtime_error(target_.string() + ": cannot move the finished report into place (" +
                                 ec.message() + ")");
      std::filesystem::remove_all(aside, ec);
    } else {
      throw std::runtime_error(target_.string() + ": cannot swap in the finished report (" +
                               std::strerror(errno) + ")");
    }
  }
  untrack_temporary(work_);
  committed_ = true;
}

}  // namespace nibrig::model::io
