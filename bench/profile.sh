#!/usr/bin/env bash
# Profiles the render + encode path with perf: a 3 s 720p60 worked-example MP4 (180 frames), and a
# still (whole process). Prints where the time goes by thread, by library and by function; the
# findings are summarised by hand in bench/results.md.
#
#   bench/profile.sh [COLLIDE_BINARY]      (default: build-bench/collide)
#   PROFILE_SECONDS=10 bench/profile.sh    (a longer render)
#
# Needs linux-perf (Debian) and perf_event_paranoid <= 2 (user-space sampling of own processes).
# llvmpipe's JIT-compiled shaders and rasteriser code have no symbols: perf shows them as
# [unknown] / "[anon]" code on the llvmpipe-N threads.
set -euo pipefail
cd "$(dirname "$0")/.."
collide=$(realpath "${1:-build-bench/collide}")
seconds=${PROFILE_SECONDS:-3}
out=${PROFILE_OUT:-/tmp/collide-profile}
command -v perf >/dev/null || {
  echo "profile: perf missing: apt-get install linux-perf" >&2
  exit 1
}
mkdir -p "$out"

profile() {
  local name=$1
  shift
  local -
  set +o pipefail  # head closes the pipe early; that is not a failure
  perf record -q -F 1999 -o "$out/$name.data" -- "$@" >"$out/$name.log" 2>&1
  {
    echo "== $name: $*"
    echo "-- by thread"
    perf report -i "$out/$name.data" --stdio --no-children --sort comm 2>/dev/null |
      grep -v '^#' | grep . | head -15
    echo "-- by library"
    perf report -i "$out/$name.data" --stdio --no-children --sort dso 2>/dev/null |
      grep -v '^#' | grep . | head -15
    echo "-- by function (top 40)"
    perf report -i "$out/$name.data" --stdio --no-children --sort dso,sym 2>/dev/null |
      grep -v '^#' | grep . | head -40
    echo
  } | tee "$out/$name.txt"
}

/usr/bin/time -f 'render: %e s wall, %U s user, %S s sys, %M KiB peak RSS' \
  "$collide" render worked-example --size 1280x720 --fps 60 --duration "$seconds" \
  -o "$out/warm.mp4" >/dev/null
profile render "$collide" render worked-example --size 1280x720 --fps 60 --duration "$seconds" \
  -o "$out/render.mp4"
profile still "$collide" still worked-example --at 2.5 --size 1280x720 -o "$out/still.png"
echo "profile: reports in $out/{render,still}.txt; perf report -i $out/render.data for more" >&2
