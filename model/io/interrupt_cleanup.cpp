#include "model/io/interrupt_cleanup.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <string>

namespace nibrig::model::io {
namespace {

enum State : int { kFree = 0, kBusy = 1, kTracked = 2 };

struct TrackedSlot {
  std::atomic<int> state{kFree};
  char path[PATH_MAX];
};

// Static and fixed, so that the signal handler reads it without allocating or locking.
constexpr std::size_t kSlots = 64;
std::array<TrackedSlot, kSlots> tracked_slots;

// Removes a folder's contents and then the folder with system calls only (opendir allocates).
// Deeper than a work folder ever nests is left: a partial cleanup beats a handler that recurses
// without bound.
void remove_tree_at(int parent, const char* name, int depth) {
  if (::unlinkat(parent, name, 0) == 0 || errno != EISDIR) return;
  if (depth > 8) return;
  const int fd = ::openat(parent, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return;
  alignas(8) char buffer[4096];
  for (;;) {
    const long n = ::syscall(SYS_getdents64, fd, buffer, sizeof buffer);
    if (n <= 0) break;
    for (long at = 0; at < n;) {
      struct Entry {
        ino64_t inode;
        off64_t offset;
        unsigned short length;
        unsigned char type;
        char name[1];
      };
      const auto* entry = reinterpret_cast<const Entry*>(buffer + at);
      at += entry->length;
      if (std::strcmp(entry->name, ".") == 0 || std::strcmp(entry->name, "..") == 0) continue;
      remove_tree_at(fd, entry->name, depth + 1);
    }
  }
  ::close(fd);
  ::unlinkat(parent, name, AT_REMOVEDIR);
}

void remove_tracked() {
  for (TrackedSlot& slot : tracked_slots)
    if (slot.state.load(std::memory_order_acquire) == kTracked) remove_tree_at(AT_FDCWD, slot.path, 0);
}

void on_signal(int signal) {
  const int saved = errno;
  remove_tracked();
  errno = saved;
  ::signal(signal, SIG_DFL);
  ::raise(signal);
}

bool claim_slot(TrackedSlot& slot, int from) {
  int expected = from;
  return slot.state.compare_exchange_strong(expected, kBusy, std::memory_order_acquire);
}

// A slot whose path is gone (a writer removed its temporary on a way out that does not untrack it)
// is free again.
void free_vanished() {
  for (TrackedSlot& slot : tracked_slots) {
    if (!claim_slot(slot, kTracked)) continue;
    struct stat info {};
    const bool gone = ::lstat(slot.path, &info) != 0 && errno == ENOENT;
    slot.state.store(gone ? kFree : kTracked, std::memory_order_release);
  }
}

bool try_track(const std::string& text) {
  for (TrackedSlot& slot : tracked_slots) {
    if (!claim_slot(slot, kFree)) continue;
    std::memcpy(slot.path, text.c_str(), text.size() + 1);
    slot.state.store(kTracked, std::memory_order_release);
    return true;
  }
  return false;
}

}  // namespace

void track_temporary(const std::filesystem::path& path) {
  const std::string text = std::filesystem::absolute(path).string();
  if (text.size() >= PATH_MAX) return;
  if (try_track(text)) return;
  free_vanished();
  try_track(text);
}

void untrack_temporary(const std::filesystem::path& path) {
  const std::string text = std::filesystem::absolute(path).string();
  for (TrackedSlot& slot : tracked_slots) {
    if (!claim_slot(slot, kTracked)) continue;
    const bool same = text == slot.path;
    slot.state.store(same ? kFree : kTracked, std::memory_order_release);
    if (same) return;
  }
}

void remove_temporaries_on_signals() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) ::sigaction(signal, &action, nullptr);
}

int tracked_temporaries() {
  int n = 0;
  for (TrackedSlot& slot : tracked_slots) n += slot.state.load(std::memory_order_acquire) == kTracked;
  return n;
}

}  // namespace nibrig::model::io
