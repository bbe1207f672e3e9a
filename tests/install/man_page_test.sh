#!/usr/bin/env bash
# The manual pages: man -l renders both without a warning (in a UTF-8 locale, and in the C locale
# as a fresh Debian has it), and collide(1) holds every option of every command's --help (names,
# type, default and description, as --help prints them) in that command's own section, so the page
# cannot drift from --help.
# Usage: man_page_test.sh COLLIDE MAN_DIR
source "$(dirname "$0")/common.sh"
collide=$1 man_dir=$2
make_temp man
# groff writes the page's non-Latin text (the language names in --lang's help) only in a UTF-8
# locale, and warns for each such character in any other; C.UTF-8 is in every Debian (libc-bin),
# so the test does not depend on the caller's LANG.
export LC_ALL=C.UTF-8
shopt -s extglob

for page in collide.1 collide-scene.5; do
  [[ -s $man_dir/$page ]] || fail "$man_dir/$page was not generated"
  warnings=$(MANWIDTH=80 man --warnings -l "$man_dir/$page" 2>&1 >"$tmp/page.txt") ||
    fail "man -l $page failed: $warnings"
  [[ -z $warnings ]] || fail "man -l $page warns: $warnings"
  # As a user without a UTF-8 locale (a fresh Debian has none) sees it: not a word on stderr.
  warnings=$(LC_ALL=C MANWIDTH=80 man -l "$man_dir/$page" 2>&1 >"$tmp/c-page.txt") ||
    fail "man -l $page failed in the C locale: $warnings"
  [[ -z $warnings ]] || fail "man -l $page warns in the C locale: $warnings"
  gzip -dc "$man_dir/$page.gz" | cmp -s - "$man_dir/$page" || fail "$page.gz is not $page"
done
MANWIDTH=80 man -l "$man_dir/collide-scene.5" 2>"$tmp/man.log" | grep -q 'restitution_law' ||
  fail "collide-scene(5) lacks the scene keys of docs/scene-format.md"

# One line per paragraph: no wrapping, whitespace squeezed.
MANWIDTH=2000 man -l "$man_dir/collide.1" >"$tmp/page.txt" 2>"$tmp/man.log"
squeeze() { tr -s ' \t\n' '   '; }

# section HEADER: the text of a subsection "collide COMMAND ..." (or a section such as OPTIONS) up
# to the next subsection or section.
section() {
  awk -v header="$1" '
    index($0, header) == 1 { inside = 1; print; next }
    inside && (/^[A-Z]/ || /^   collide /) { exit }
    inside { print }' "$tmp/page.txt" | squeeze
}

# check_command WORDS...: every option and positional of `collide WORDS --help` in its section;
# then the same for each of its subcommands.
check_command() {
  local help text header spec description line next subcommands checked=0
  help=$("$collide" "$@" --help) || fail "collide $* --help failed"
  if (($#)); then header="   collide $*"; else header="OPTIONS"; fi
  text=$(section "$header")
  [[ -n $text ]] || fail "collide(1) has no section '$header'"
  while IFS= read -r line; do
    # "  -o,--output TEXT REQUIRED   Output path": the spec ends at the first double space; a long
    # spec has its description on the next line.
    [[ $line =~ ^\ \ [-A-Z] ]] || continue
    spec=${line:2}
    spec=${spec%%  *}
    description=${line:2+${#spec}}
    description=${description#"${description%%[! ]*}"}
    if [[ -z $description ]]; then
      next=$(grep -A1 -xF -- "$line" <<<"$help" | sed -n 2p)
      description=${next#"${next%%[! ]*}"}
    fi
    local names=${spec%% *} rest=""
    [[ $spec == *" "* ]] && rest=" ${spec#* }"
    local expected words
    # Whitespace squeezed by splitting into words: an extglob substitution over the long --lang
    # description (its language names are multibyte) took seconds per option.
    read -ra words <<<"${names//,/, }$rest $description"
    expected="${words[*]}"
    # groff's UTF-8 output drops the Devanagari virama (U+094D: "हिन्दी" in the language list
    # comes out "हिनदी"), so it is not looked for.
    expected=${expected//$'\xe0\xa5\x8d'/}
    [[ $text == *" $expected"* ]] ||
      fail "collide(1), section '$header', lacks '$expected' from 'collide $* --help'"
    checked=$((checked + 1))
  done <<<"$help"
  ((checked > 0)) || fail "no options found in 'collide $* --help'"
  subcommands=$(awk '/^Subcommands:/ { on = 1; next } on && /^  [a-z]/ { print $1 } /^$/ { on = 0 }' <<<"$help")
  local subcommand
  for subcommand in $subcommands; do check_command "$@" "$subcommand"; done
  total=$((total + checked))
}

total=0
check_command
echo "collide(1) holds all $total options and positionals of every command's --help"
