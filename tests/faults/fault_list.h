// Shared by the fault shims: whether a name is on a comma-separated list taken from the
// environment, e.g. COLLIDE_FAULT_GL=osmesa,egl. Test-only; never linked into collide itself.
#ifndef COLLIDE_FAULT_LIST_H
#define COLLIDE_FAULT_LIST_H

#include <dlfcn.h>
#include <stdlib.h>
#include <string.h>

// Sets the function pointer `real` to the next definition of `name` after the shim's own (the
// real library's). Copied, not cast: ISO C has no cast from dlsym's void* to a function pointer.
#define COLLIDE_FAULT_NEXT(real, name)                \
  do {                                                \
    void* const next_symbol = dlsym(RTLD_NEXT, name); \
    memcpy(&(real), &next_symbol, sizeof(real));      \
  } while (0)

// True when `name` is one of the comma-separated entries of the variable `list_variable`.
static inline int faultListHas(const char* list_variable, const char* name) {
  const char* list = getenv(list_variable);
  if (list == NULL || name == NULL) return 0;
  const size_t length = strlen(name);
  for (const char* entry = list; *entry != '\0';) {
    const char* end = strchr(entry, ',');
    const size_t entry_length = end != NULL ? (size_t)(end - entry) : strlen(entry);
    if (entry_length == length && strncmp(entry, name, length) == 0) return 1;
    if (end == NULL) break;
    entry = end + 1;
  }
  return 0;
}

// True when `path` ends in one of the entries of `list_variable` (as a whole file name), e.g.
// "DejaVuSans.ttf" matches "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf".
static inline int faultListHasFileOf(const char* list_variable, const char* path) {
  if (path == NULL) return 0;
  const char* slash = strrchr(path, '/');
  return faultListHas(list_variable, slash != NULL ? slash + 1 : path);
}

#endif
