// LD_PRELOAD fault: files that are not there. Opening any file whose name (the part after the
// last '/') is listed in COLLIDE_FAULT_HIDDEN_FILES fails with ENOENT, e.g.
// COLLIDE_FAULT_HIDDEN_FILES=DejaVuSans.ttf stands for a machine without fonts-dejavu-core.
// FreeType opens fonts with open(2); fopen is covered too.
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdio.h>

#include "fault_list.h"

static int hidden(const char* path) {
  return faultListHasFileOf("COLLIDE_FAULT_HIDDEN_FILES", path);
}

// The mode argument exists only when a file may be created.
static mode_t modeArgument(int flags, va_list arguments) {
  return (flags & O_CREAT) || (flags & O_TMPFILE) == O_TMPFILE ? va_arg(arguments, mode_t) : 0;
}

#define COLLIDE_INTERPOSE_OPEN(function)                \
  int function(const char* path, int flags, ...) {      \
    va_list arguments;                                  \
    va_start(arguments, flags);                         \
    const mode_t mode = modeArgument(flags, arguments); \
    va_end(arguments);                                  \
    if (hidden(path)) {                                 \
      errno = ENOENT;                                   \
      return -1;                                        \
    }                                                   \
    typedef int (*Real)(const char*, int, ...);         \
    Real real;                                          \
    COLLIDE_FAULT_NEXT(real, #function);                \
    return real(path, flags, mode);                     \
  }

COLLIDE_INTERPOSE_OPEN(open)
COLLIDE_INTERPOSE_OPEN(open64)

#define COLLIDE_INTERPOSE_FOPEN(function)              \
  FILE* function(const char* path, const char* mode) { \
    if (hidden(path)) {                                \
      errno = ENOENT;                                  \
      return NULL;                                     \
    }                                                  \
    typedef FILE* (*Real)(const char*, const char*);   \
    Real real;                                         \
    COLLIDE_FAULT_NEXT(real, #function);               \
    return real(path, mode);                           \
  }

COLLIDE_INTERPOSE_FOPEN(fopen)
COLLIDE_INTERPOSE_FOPEN(fopen64)
