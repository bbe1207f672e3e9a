#!/usr/bin/env bash
# scripts/check-modules catches each kind of broken module rule: a copy of src/ passes as it is,
# and fails, naming the offence, once one violation is planted in it (a forbidden include, a
# drawing library, a forbidden link, app reaching into layout, app grown past 15 %).
# Usage: check_modules_test.sh SOURCE_DIR
set -euo pipefail
source_dir=$1
check=$source_dir/scripts/check-modules
scratch=$(mktemp -d "${TMPDIR:-/tmp}/collide-check-modules.XXXXXX")
trap 'rm -rf "$scratch"' EXIT

fresh_copy() {
  rm -rf "$scratch/tree"
  mkdir -p "$scratch/tree"
  cp -r "$source_dir/src" "$scratch/tree/src"
}

failures=0
# Every planted violation but the long function's is checked without rule 6 (short functions):
# the unchanged copy shows it passes, and it takes most of a run's time.
expect_failure() {
  local what=$1 expected=$2 output skip_lengths=1
  [[ "$what" == *"a function of"* ]] && skip_lengths=
  if output=$(CHECK_MODULES_SKIP_LENGTHS=$skip_lengths bash "$check" "$scratch/tree" 2>&1); then
    echo "FAIL: $what: check-modules passed" >&2
    failures=$((failures + 1))
  elif ! grep -qF -- "$expected" <<<"$output"; then
    echo "FAIL: $what: the message does not name '$expected':" >&2
    echo "$output" >&2
    failures=$((failures + 1))
  fi
}

fresh_copy
bash "$check" "$scratch/tree" >"$scratch/passed.log" || { echo "FAIL: the unchanged copy fails" >&2; exit 1; }

fresh_copy
echo '#include "output/frame_sink.hpp"' >>"$scratch/tree/src/compose/palette.cpp"
expect_failure "compose including output" "src/compose/palette.cpp"

fresh_copy
echo '#include "render/draw/canvas.hpp"' >>"$scratch/tree/src/compose/palette.cpp"
expect_failure "compose including a render painter header" "render/draw/canvas.hpp"

fresh_copy
echo '#include "render/renderer.hpp"' >>"$scratch/tree/src/compose/palette.cpp"
expect_failure "compose including anything of render" "render/renderer.hpp"

fresh_copy
echo '#include "compose/palette.hpp"' >>"$scratch/tree/src/render/draw/canvas.cpp"
expect_failure "render including compose" "src/render/draw/canvas.cpp"

fresh_copy
echo '#include "render/draw/canvas.hpp"' >>"$scratch/tree/src/frame/layout.cpp"
expect_failure "the frame description including render" "src/frame/layout.cpp"

fresh_copy
echo '#include "render/renderer.hpp"' >>"$scratch/tree/src/render/text/font.cpp"
expect_failure "render's text layer including the Renderer" "src/render/text/font.cpp"

fresh_copy
echo '#include "render/gl/gl_check.hpp"' >>"$scratch/tree/src/render/vector/svg_text.cpp"
expect_failure "the vector painter including the GL painter" "src/render/vector/svg_text.cpp"

fresh_copy
echo '#include "compose/palette.hpp"' >>"$scratch/tree/src/physics/toi.cpp"
expect_failure "physics including compose" "src/physics/toi.cpp"

fresh_copy
echo '#include <cairo.h>' >>"$scratch/tree/src/compose/palette.cpp"
expect_failure "compose including Cairo" "<cairo.h>"

fresh_copy
sed -i 's/collide_frame)/collide_frame collide_render_base)/' \
  "$scratch/tree/src/compose/CMakeLists.txt"
expect_failure "compose linking the painters" "collide_render_base"

fresh_copy
sed -i 's/collide_frame)/collide_frame collide_render_text)/' \
  "$scratch/tree/src/compose/CMakeLists.txt"
expect_failure "compose linking the font libraries" "collide_render_text"

fresh_copy
echo '#include "render/text/text_metrics.hpp"' >>"$scratch/tree/src/compose/palette.cpp"
expect_failure "compose including the painters' own text metrics" "render/text/text_metrics.hpp"

fresh_copy
echo '#include "frame/layout.hpp"' >>"$scratch/tree/src/app/cli.cpp"
expect_failure "app including the pixel layout" "src/app/cli.cpp"

fresh_copy
{
  echo 'int plantedLongFunction(int x) {'
  for ((line = 0; line < 80; ++line)); do echo '  x += 1;'; done
  echo '  return x;'
  echo '}'
} >>"$scratch/tree/src/core/error.cpp"
expect_failure "a function of 83 lines" "plantedLongFunction is 83 lines"

fresh_copy
# The fewest lines n that take app to 15 % of src/: 15 (src + n) <= 100 (app + n), i.e.
# 85 n >= 15 src - 100 app (exact integers: a tree where that difference divides by 85 is the edge).
src_lines=$(find "$scratch/tree/src" \( -name '*.cpp' -o -name '*.hpp' \) -print0 | xargs -0 cat | wc -l)
app_lines=$(find "$scratch/tree/src/app" \( -name '*.cpp' -o -name '*.hpp' \) -print0 | xargs -0 cat | wc -l)
extra=$(((15 * src_lines - 100 * app_lines - 1) / 85 + 1))
((extra > 0)) || extra=1
for ((line = 0; line < extra - 1; ++line)); do echo '// filler'; done >"$scratch/tree/src/app/filler.cpp"
CHECK_MODULES_SKIP_LENGTHS=1 bash "$check" "$scratch/tree" >"$scratch/passed.log" || {
  echo "FAIL: app just under 15 % of src/ fails" >&2
  failures=$((failures + 1))
}
for ((line = 0; line < extra; ++line)); do echo '// filler'; done >"$scratch/tree/src/app/filler.cpp"
expect_failure "app at 15 % of src/" "src/app is too large"

((failures == 0)) || exit 1
echo "check_modules_test: every planted violation caught"
