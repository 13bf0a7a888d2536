#include "model/io/folder_result.hpp"

#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string_view>
#include <system_error>

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
    const bool empty = std::filesystem::is_empty(target_, ec);
    if (!empty && !std::filesystem::exists(target_ / marker))
      throw std::runtime_error(target_.string() + ": holds files but no " + marker +
                               ", so it is not an earlier report to replace; name a new or "
                               "empty folder");
  }
  remove_abandoned_work(target_);
  work_ = target_.parent_path() / (work_prefix(target_) + std::to_string(::getpid()));
  std::filesystem::remove_all(work_, ec);
  std::filesystem::create_directories(work_, ec);
  if (ec)
    throw std::runtime_error(work_.string() + ": cannot make the folder to build the report in (" +
                             ec.message() + ")");
}

FolderResult::~FolderResult() {
  if (committed_) return;
  std::error_code ec;
  std::filesystem::remove_all(work_, ec);
}

void FolderResult::commit() {
  std::error_code ec;
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
  committed_ = true;
}

}  // namespace nibrig::model::io
