#!/usr/bin/env bash
# Builds the .deb with CPack into a temporary directory and checks it: name, version, that its
# Depends cover every shared library the binary links (each library's package as dpkg -S sees it)
# and every library it loads while rendering through OSMesa and EGL (covered when the library's
# package is declared or pulled in by a declared package), the font it opens; then unpacks it with
# dpkg -x into a temporary root (never the machine's own) and renders from there.
# Usage: deb_package_test.sh SOURCE_DIR BUILD_DIR VERSION
source "$(dirname "$0")/common.sh"
source_dir=$1 build_dir=$2 version=$3
make_temp deb

cpack --config "$build_dir/CPackConfig.cmake" -B "$tmp/package" >"$tmp/cpack.log" 2>&1 ||
  { cat "$tmp/cpack.log" >&2; fail "cpack failed"; }
deb=$(echo "$tmp"/package/collide_*.deb)
[[ -f $deb ]] || fail "cpack made no collide_*.deb"
[[ $(dpkg-deb --field "$deb" Package) == collide ]] || fail "package name is not collide"
[[ $(dpkg-deb --field "$deb" Version) == "$version" ]] || fail "package version is not $version"
[[ -n $(dpkg-deb --field "$deb" Description) ]] || fail "package has no description"
depends=$(dpkg-deb --field "$deb" Depends)
echo "Depends: $depends"
# Package names only: "libpng16-16 (>= 1.6.2-1), a | b" -> libpng16-16 a b.
names_of() { tr ',|' '\n\n' | sed -E 's/\(.*\)//; s/:any//; s/^ +//; s/ +$//' | grep -v '^$' || true; }
mapfile -t declared < <(names_of <<<"$depends")
declare -A is_declared=()
for package in "${declared[@]}"; do is_declared[$package]=1; done

# owners PATH...: "PATH<TAB>PACKAGE" per path, the package that installed it as dpkg -S sees it.
# dpkg may have a library under /lib or /usr/lib, or under a symlink's name; one dpkg -S call asks
# for every spelling (a call per library would cost seconds).
owners() {
  local path real
  local -A spellings=()
  for path in "$@"; do
    real=$(realpath "$path")
    spellings[$path]="$path $real ${path#/usr} ${real#/usr} /usr$path /usr$real"
  done
  local -A owner_of=()
  local line
  while IFS= read -r line; do
    # "libpng16-16:amd64: /usr/lib/x86_64-linux-gnu/libpng16.so.16"
    owner_of[${line#*: }]=${line%%: *}
  done < <(dpkg -S ${spellings[@]} 2>"$tmp/unowned.log" || true)
  for path in "$@"; do
    local spelling package=""
    for spelling in ${spellings[$path]}; do
      package=${owner_of[$spelling]:-}
      [[ -n $package ]] && break
    done
    [[ -n $package ]] || fail "no package owns $path"
    printf '%s\t%s\n' "$path" "${package%%[:,]*}"
  done
}

root=$tmp/root
dpkg -x "$deb" "$root"
collide=$root/usr/bin/collide
[[ -x $collide ]] || fail "the package has no usr/bin/collide"
for file in usr/share/man/man1/collide.1.gz usr/share/man/man5/collide-scene.5.gz \
  usr/share/bash-completion/completions/collide usr/share/zsh/vendor-completions/_collide \
  usr/share/doc/collide/docs/scene-format.md usr/lib/collide/collide-video.so \
  usr/lib/collide/collide-gl.so usr/lib/collide/collide-vector.so; do
  [[ -f $root/$file ]] || fail "the package lacks $file"
done

# Every library that the binary and the modules it opens (collide-video.so, collide-gl.so,
# collide-vector.so) link: their DT_NEEDED entries, resolved as the loader does.
mapfile -t programs < <(find "$root" -type f \( -path '*/bin/*' -o -name '*.so' \))
((${#programs[@]} >= 4)) || fail "the package lacks the video, GL or vector module beside bin/collide: ${programs[*]}"
linked=()
for program in "${programs[@]}"; do
  needed=$(readelf -d "$program" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p')
  [[ -n $needed ]] || fail "readelf found no linked libraries in $program"
  resolved=$(ldd "$program")
  for library in $needed; do
    # The dynamic loader itself (linked where position-independent code calls __tls_get_addr,
    # as the Python module's build makes it) is listed by ldd as its path alone.
    path=$(awk -v name="$library" '$1 == name { print $3 }
      substr($1, length($1) - length(name)) == "/" name { print $1 }' <<<"$resolved")
    [[ -f $path ]] || fail "$library, linked by $program, is not found by the loader"
    linked+=("$path")
  done
done
mapfile -t linked < <(printf '%s\n' "${linked[@]}" | sort -u)
while IFS=$'\t' read -r path package; do
  [[ -n ${is_declared[$package]:-} ]] ||
    fail "collide links $path (package $package), which Depends does not declare"
done < <(owners "${linked[@]}")
[[ -n ${is_declared[fonts-dejavu-core]:-} ]] || fail "Depends lacks fonts-dejavu-core (the default font)"
[[ -n ${is_declared[fonts-dejavu-extra]:-} ]] ||
  fail "Depends lacks fonts-dejavu-extra (DejaVu Math TeX Gyre, the working's math font)"

# Render from the unpacked root with the trees out of sight, noting every library loaded.
mkdir "$tmp/elsewhere"
cd "$tmp/elsewhere"
LD_DEBUG=libs LD_DEBUG_OUTPUT=$tmp/loaded-osmesa render_both "$collide" "$source_dir" "$build_dir"
LD_DEBUG=libs LD_DEBUG_OUTPUT=$tmp/loaded-egl without_trees "$source_dir" "$build_dir" \
  "$collide" still worked-example --at 1 --size 64x64 --backend egl -o egl.png ||
  fail "the unpacked collide cannot render through EGL"
check_png egl.png 64 64

# Packages reachable from Depends through the Depends and Pre-Depends of installed packages.
declare -A reachable=()
frontier=("${declared[@]}")
while ((${#frontier[@]})); do
  for package in "${frontier[@]}"; do reachable[$package]=1; done
  mapfile -t next < <({ dpkg-query -W -f='${Depends}, ${Pre-Depends}\n' "${frontier[@]}" 2>"$tmp/not-installed.log" || true; } |
    names_of | sed 's/:.*//' | sort -u)
  frontier=()
  for package in "${next[@]}"; do
    [[ -n ${reachable[$package]:-} ]] || frontier+=("$package")
  done
done
mapfile -t loaded < <(cat "$tmp"/loaded-* | sed -n 's/.*calling init: //p' | sort -u)
((${#loaded[@]} > 5)) || fail "LD_DEBUG recorded no loaded libraries"
missing=()
while IFS=$'\t' read -r path package; do
  [[ -n ${reachable[$package]:-} ]] || missing+=("$path (package $package)")
done < <(owners $(printf '%s\n' "${loaded[@]}" | grep -v "^$root/"))
((${#missing[@]} == 0)) ||
  fail "rendering loads libraries that no declared dependency brings in: ${missing[*]}"
echo "the .deb declares what collide links and loads (${#loaded[@]} libraries) and runs unpacked"
