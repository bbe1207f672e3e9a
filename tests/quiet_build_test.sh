#!/usr/bin/env bash
# scripts/build-quietly (what scripts/setup builds with) on a small project: a successful build
# prints the compiler's warning and nothing else (no progress line, no custom command's comment);
# a failed one prints the error and fails.
# Usage: quiet_build_test.sh SOURCE_DIR
set -euo pipefail
source_dir=$1
scratch=$(mktemp -d "${TMPDIR:-/tmp}/collide-quiet-build.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
export LC_ALL=C  # the compiler's words in English, whatever the caller's locale
fail() {
  echo "FAIL: $*" >&2
  exit 1
}

mkdir "$scratch/project"
cat >"$scratch/project/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.25)
project(quiet C)
add_custom_command(OUTPUT generated.h COMMAND ${CMAKE_COMMAND} -E touch generated.h
                   COMMENT "Embedding nothing into generated.h")
add_executable(warns warns.c ${CMAKE_CURRENT_BINARY_DIR}/generated.h)
target_include_directories(warns PRIVATE ${CMAKE_CURRENT_BINARY_DIR})
target_compile_options(warns PRIVATE -Wall)
add_executable(broken EXCLUDE_FROM_ALL broken.c)
CMAKE
printf '#include "generated.h"\nint main(void) { int unused_here; return 0; }\n' >"$scratch/project/warns.c"
printf 'int main(void) { return undeclared_here; }\n' >"$scratch/project/broken.c"
cmake -S "$scratch/project" -B "$scratch/build" >"$scratch/configure.log" 2>&1 ||
  { cat "$scratch/configure.log" >&2; fail "the test project does not configure"; }

output=$("$source_dir/scripts/build-quietly" "$scratch/build" 2>&1) ||
  fail "the build failed: $output"
grep -q "warning: unused variable 'unused_here'" <<<"$output" || fail "the warning is missing: $output"
# The compiler's lines name the file or are its indented context ("    2 | int main...").
noise=$(grep -vE 'warns\.c|^ ' <<<"$output" || true)
[[ -z $noise ]] || fail "a successful build printed more than its warning: $noise"

if output=$("$source_dir/scripts/build-quietly" "$scratch/build" broken 2>&1); then
  fail "a failed build exits 0: $output"
fi
grep -q "error: 'undeclared_here' undeclared" <<<"$output" || fail "the error is missing: $output"
echo "a successful build printed only its warning; a failed one its error"
