#!/usr/bin/env bash
# `cmake --install` into a temporary prefix; the installed tree is moved elsewhere and its collide
# renders a still and a short MP4 from another directory with the source and build trees out of
# sight. Usage: install_test.sh SOURCE_DIR BUILD_DIR VERSION
source "$(dirname "$0")/common.sh"
source_dir=$1 build_dir=$2 version=$3
make_temp install

cmake --install "$build_dir" --prefix "$tmp/prefix" >"$tmp/install.log" 2>&1 ||
  { cat "$tmp/install.log" >&2; fail "cmake --install failed"; }
mv "$tmp/prefix" "$tmp/moved"  # nothing may depend on where it was installed either
prefix=$tmp/moved
for file in bin/collide lib/collide/collide-video.so lib/collide/collide-gl.so lib/collide/collide-vector.so share/man/man1/collide.1.gz share/man/man5/collide-scene.5.gz \
  share/bash-completion/completions/collide share/zsh/site-functions/_collide \
  share/doc/collide/README.md share/doc/collide/docs/scene-format.md \
  share/doc/collide/docs/cluster.md; do
  [[ -f $prefix/$file ]] || fail "cmake --install did not install $file"
done
[[ -x $prefix/bin/collide ]] || fail "bin/collide is not executable"

mkdir "$tmp/elsewhere"
cd "$tmp/elsewhere"
[[ $(without_trees "$source_dir" "$build_dir" "$prefix/bin/collide" --version) == "collide $version" ]] ||
  fail "installed collide --version does not print 'collide $version'"
render_both "$prefix/bin/collide" "$source_dir" "$build_dir"
echo "installed tree renders a still and an MP4 on its own"
