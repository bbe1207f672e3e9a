# Shared by the install tests (sourced): failing with one clear line, a private temporary directory,
# running a command with the source and build trees out of sight, and checks of rendered files.
set -euo pipefail

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# make_temp NAME: $tmp, a fresh directory removed on exit.
make_temp() {
  tmp=$(mktemp -d "${TMPDIR:-/tmp}/collide-$1.XXXXXX")
  trap 'rm -rf "$tmp"' EXIT
}

# without_trees SOURCE_DIR BUILD_DIR COMMAND...: runs COMMAND in a private mount namespace where
# both trees are empty directories, so an installed collide that still reached into either fails.
# Where mount namespaces are not allowed, COMMAND runs as it is and a note says the trees stayed
# visible (the installed tree was still moved away from where it was installed).
without_trees() {
  local source_dir=$1 build_dir=$2
  shift 2
  if unshare --mount --propagation private true 2>"$tmp/unshare.log"; then
    unshare --mount --propagation private bash -c \
      'mount -t tmpfs hidden-build "$1" && mount -t tmpfs hidden-source "$2" && shift 2 && exec "$@"' \
      without_trees "$build_dir" "$source_dir" "$@"
  else
    echo "note: no mount namespace here; the source and build trees stay visible" >&2
    "$@"
  fi
}

# check_png FILE WIDTH HEIGHT: a PNG of that size (IHDR: width and height, 4 bytes big-endian each,
# at offset 16).
check_png() {
  [[ -s $1 ]] || fail "$1 was not written"
  [[ $(head -c 8 "$1" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]] || fail "$1 is not a PNG"
  local size
  size=$(od -An -tu1 -j16 -N8 "$1" | awk '{ print $1*16777216 + $2*65536 + $3*256 + $4 "x" $5*16777216 + $6*65536 + $7*256 + $8 }')
  [[ $size == "$2x$3" ]] || fail "$1 is $size, expected $2x$3"
}

# check_mp4 FILE: an MP4 (ftyp box first) holding an H.264 track and its index (moov).
check_mp4() {
  [[ -s $1 ]] || fail "$1 was not written"
  [[ $(head -c 8 "$1" | tail -c 4) == ftyp ]] || fail "$1 does not start with an ftyp box"
  grep -q avc1 "$1" || fail "$1 has no H.264 (avc1) track"
  grep -q moov "$1" || fail "$1 has no moov box"
}

# render_both COLLIDE SOURCE_DIR BUILD_DIR: from the current directory, a 320x180 still, an SVG
# figure (the vector module) and a short MP4 with the trees out of sight.
render_both() {
  local collide=$1 source_dir=$2 build_dir=$3
  without_trees "$source_dir" "$build_dir" "$collide" still worked-example --at 2 --size 320x180 \
    -o still.png || fail "$collide still failed"
  check_png still.png 320 180
  without_trees "$source_dir" "$build_dir" "$collide" still worked-example --at 2 --size 320x180 \
    -o figure.svg || fail "$collide still to SVG failed"
  grep -q '<svg' figure.svg || fail "$collide wrote no SVG document"
  without_trees "$source_dir" "$build_dir" "$collide" render worked-example --duration 0.5 \
    --fps 10 --size 320x180 -o clip.mp4 2>render.log || { cat render.log >&2; fail "$collide render failed"; }
  check_mp4 clip.mp4
}
