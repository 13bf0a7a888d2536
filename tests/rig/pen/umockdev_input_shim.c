/* Two things umockdev 0.17 leaves out that a reader of input devices needs, added for the pen tests
 * only (preloaded before umockdev's library by run_under_umockdev.sh):
 *  - udev's database: /run/udev/data/<id> is read from the testbed ($UMOCKDEV_DIR/run/udev/data), so
 *    a device the test describes there is "initialised", as udevd would have made it; without it
 *    libudev calls every emulated device uninitialised and libinput skips it (umockdev issue #267).
 *  - fstat on an emulated node: umockdev backs a character device with a pty and fakes its device
 *    number for stat() by path, but glibc's fstat does not pass through stat(), so libinput's check
 *    that the node it opened is the device udev named saw the pty's number. Here fstat of a testbed
 *    pty answers as stat() of the node the testbed links to it.
 * And one thing it gets wrong: each failed open of a /dev node it does not have still takes a slot
 * of its fd map, so ALSA's probe of 32 cards' control nodes (a `nibrig devices` child) overflows it
 * and aborts. The testbed has no sound cards: their nodes are refused here, before umockdev. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <ftw.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const char kUdevData[] = "/run/udev/data/";

/* The testbed's copy of a udev database path, in `out`; NULL when `path` is not one. */
static const char* shim_udev_path(const char* path, char* out, size_t size) {
  const char* root = getenv("UMOCKDEV_DIR");
  if (!root || !path || strncmp(path, kUdevData, sizeof kUdevData - 1) != 0) return NULL;
  snprintf(out, size, "%s%s", root, path);
  return out;
}

#define SHIM_NEXT(type, name) ((type)dlsym(RTLD_NEXT, name))

/* A sound card's node, which the testbed never has. */
static int shim_sound_node(const char* path) {
  return getenv("UMOCKDEV_DIR") && path && (strncmp(path, "/dev/snd/", 9) == 0 || strncmp(path, "/dev/aloadC", 11) == 0);
}

/* open's mode argument, there only when the flags create a file. */
#define SHIM_MODE(flags, mode)                \
  mode_t mode = 0;                            \
  if ((flags) & (O_CREAT | O_TMPFILE)) {      \
    va_list ap;                               \
    va_start(ap, flags);                      \
    mode = va_arg(ap, mode_t);                \
    va_end(ap);                               \
  }

/* A sound card's node: refused (ENOENT, -1 returned by the caller) before umockdev sees it. */
static int shim_refused(const char* path) {
  if (!shim_sound_node(path)) return 0;
  errno = ENOENT;
  return 1;
}

int open64(const char* path, int flags, ...) {
  SHIM_MODE(flags, mode)
  if (shim_refused(path)) return -1;
  char moved[4096];
  const char* p = shim_udev_path(path, moved, sizeof moved);
  return SHIM_NEXT(int (*)(const char*, int, ...), "open64")(p ? p : path, flags, mode);
}

int openat64(int dirfd, const char* path, int flags, ...) {
  SHIM_MODE(flags, mode)
  if (shim_refused(path)) return -1;
  char moved[4096];
  const char* p = shim_udev_path(path, moved, sizeof moved);
  return SHIM_NEXT(int (*)(int, const char*, int, ...), "openat64")(dirfd, p ? p : path, flags, mode);
}

int open(const char* path, int flags, ...) {
  SHIM_MODE(flags, mode)
  if (shim_refused(path)) return -1;
  return SHIM_NEXT(int (*)(const char*, int, ...), "open")(path, flags, mode);
}

int __open_2(const char* path, int flags) {
  if (shim_refused(path)) return -1;
  return SHIM_NEXT(int (*)(const char*, int), "__open_2")(path, flags);
}

FILE* fopen64(const char* path, const char* mode) {
  char moved[4096];
  const char* p = shim_udev_path(path, moved, sizeof moved);
  return SHIM_NEXT(FILE* (*)(const char*, const char*), "fopen64")(p ? p : path, mode);
}

/* The node under $UMOCKDEV_DIR/dev whose symlink points at `pty`, found by walking the testbed. */
static __thread char shim_pty[4096];
static __thread char shim_node[4096];
static __thread size_t shim_root_length;

static int shim_visit(const char* path, const struct stat* st, int type, struct FTW* ftw) {
  (void)st;
  (void)ftw;
  if (type != FTW_SL) return 0;
  char target[4096];
  const ssize_t n = readlink(path, target, sizeof target - 1);
  if (n <= 0) return 0;
  target[n] = '\0';
  if (strcmp(target, shim_pty) != 0) return 0;
  snprintf(shim_node, sizeof shim_node, "%s", path + shim_root_length);
  return 1;
}

int fstat64(int fd, struct stat64* st) {
  const char* root = getenv("UMOCKDEV_DIR");
  if (root) {
    char link[64];
    snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
    const ssize_t n = readlink(link, shim_pty, sizeof shim_pty - 1);
    if (n > 0) {
      shim_pty[n] = '\0';
      if (strncmp(shim_pty, "/dev/pts/", 9) == 0) {
        char dev[4096];
        snprintf(dev, sizeof dev, "%s/dev", root);
        shim_root_length = strlen(root);
        shim_node[0] = '\0';
        nftw(dev, shim_visit, 8, FTW_PHYS);
        /* stat() of the /dev path goes through umockdev, which gives the emulated device number. */
        if (shim_node[0]) return stat64(shim_node, st);
      }
    }
  }
  return SHIM_NEXT(int (*)(int, struct stat64*), "fstat64")(fd, st);
}

int fstat(int fd, struct stat* st) { return fstat64(fd, (struct stat64*)st); }
