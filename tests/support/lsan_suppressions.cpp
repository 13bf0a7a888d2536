// tests/lsan.supp, built in: LeakSanitizer asks every process for its default suppressions, so a
// test binary run by hand (without ctest's LSAN_OPTIONS) leaves out the same leaks of other
// libraries. Unused in a binary built without a sanitizer.
extern "C" const char* __lsan_default_suppressions() {
  return
#include "lsan_suppressions.inc"
      ;
}
