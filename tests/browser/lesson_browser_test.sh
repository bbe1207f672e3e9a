#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# collide lesson's pages in a real browser (issue 43): the worked example in English and the
# ballistic pendulum in Arabic (right to left), each loaded from disk by headless Chromium at 1280
# and 360 px wide and checked by check_lesson_page.js (video, captions, images, MathML, width,
# axe-core). Skipped (exit 77) with the reason where Chromium, Node.js or the npm modules
# (puppeteer-core, axe-core; scripts/install-browser-test) are missing.
# Usage: lesson_browser_test.sh COLLIDE_BINARY. COLLIDE_LESSON_SHOTS=DIR also writes screenshots
# of both pages at both widths into DIR.
set -euo pipefail
collide=$1
here=$(cd "$(dirname "$0")" && pwd)
modules=${COLLIDE_BROWSER_MODULES:-/usr/local/lib/collide-browser-test/node_modules}
skip() {
  echo "LessonBrowserGLTest SKIPPED: $*; scripts/install-packages installs it" >&2
  exit 77
}
chromium=$(command -v chromium || command -v chromium-browser || true)
[[ -n $chromium ]] || skip "no Chromium (Debian's chromium package)"
[[ -n $(command -v node || true) ]] || skip "no Node.js"
[[ -f $modules/puppeteer-core/package.json && -f $modules/axe-core/axe.min.js ]] ||
  skip "no puppeteer-core and axe-core in $modules"

scratch=$(mktemp -d "${TMPDIR:-/tmp}/collide-lesson-browser.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
# Chromium's profile, caches and crash reports stay in the test's own folder.
export HOME=$scratch TMPDIR=$scratch XDG_CONFIG_HOME=$scratch/config XDG_CACHE_HOME=$scratch/cache

# Small videos: the page, not the encoder, is under test.
"$collide" lesson worked-example -o "$scratch/en/" --size 640x360 --fps 15 >"$scratch/en.log"
"$collide" lesson ballistic-pendulum --lang ar -o "$scratch/ar/" --size 640x360 --fps 15 >"$scratch/ar.log"

shots=()
failed=0
for page in "en en ltr worked-example" "ar ar rtl ballistic-pendulum"; do
  read -r folder lang dir name <<<"$page"
  [[ -n ${COLLIDE_LESSON_SHOTS:-} ]] && shots=(--shots "$COLLIDE_LESSON_SHOTS/$name-$lang")
  echo "== $name ($lang)"
  timeout 120 node "$here/check_lesson_page.js" "$modules" "$chromium" \
    "$scratch/$folder/index.html" "$lang" "$dir" 1280 360 "${shots[@]}" || failed=1
done
exit $failed
