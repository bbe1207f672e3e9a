#!/usr/bin/env bash
# The shell completions complete what a user types: commands, options, option values, preset
# names (those `collide presets` lists) and file paths. bash: the script is sourced and its
# function called as bash calls it on <TAB>. zsh: the completion function runs with the
# completion system's _describe, _values and _files replaced by stubs that print what they are
# offered. Usage: completion_test.sh COLLIDE SOURCE_DIR
source "$(dirname "$0")/common.sh"
collide=$(realpath "$1")
source_dir=$2
make_temp completion
mkdir "$tmp/bin" "$tmp/scenes"
ln -s "$collide" "$tmp/bin/collide"  # completed as plain `collide`, found on PATH
export PATH="$tmp/bin:$PATH"
: >"$tmp/scenes/carts.toml"
cd "$tmp"

mapfile -t presets < <(collide presets | awk '{ print $1 }')
((${#presets[@]} > 5)) || fail "collide presets listed no presets"

# --- bash ---
source "$source_dir/completions/collide.bash"
[[ $(complete -p collide) == *"-F _collide"* ]] || fail "the bash script does not register _collide"
# offer WORDS...: got = what <TAB> offers after WORDS (the last word is the one being completed),
# one per line. Called in this shell, not a subshell, so the script's cache works as in a session.
offer() {
  COMP_WORDS=("$@")
  COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
  COMP_LINE="$*"
  COMP_POINT=${#COMP_LINE}
  COMPREPLY=()
  _collide collide "${COMP_WORDS[COMP_CWORD]}" "${COMP_WORDS[COMP_CWORD - 1]}"
  got=$(printf '%s\n' "${COMPREPLY[@]}")
}
# expect SHELL "TYPED" WORD...: each WORD is among what was offered ($got).
expect() {
  local shell=$1 typed=$2 word
  shift 2
  for word in "$@"; do
    grep -qxF -- "$word" <<<"$got" || fail "$shell: '$typed<TAB>' offers '${got//$'\n'/ }', not '$word'"
  done
}
# expect_only SHELL "TYPED" WORD: exactly WORD is offered (it completes).
expect_only() {
  [[ $got == "$3" ]] || fail "$1: '$2<TAB>' offers '${got//$'\n'/ }', not just '$3'"
}
offer collide ren && expect_only bash "collide ren" render
offer collide still --the && expect bash "collide still --the" --theme
offer collide still --them && expect_only bash "collide still --them" --theme
offer collide still '' && expect bash "collide still " "${presets[@]}"
offer collide still wor && expect_only bash "collide still wor" worked-example
offer collide still scenes/c && expect_only bash "collide still scenes/c" scenes/carts.toml
offer collide render '' && expect bash "collide render " "${presets[@]}" scenes
offer collide presets show '' && expect bash "collide presets show " "${presets[@]}"
offer collide '' && expect bash "collide " render still strobe chart data presets check batch info
[[ $got != *help-man* ]] || fail "bash: the hidden help-man is offered"
offer collide still - && expect bash "collide still -" -o --output --at --size --set
offer collide render --backend = '' && expect bash "collide render --backend=" osmesa egl gpu auto
offer collide still -o scenes/ && expect_only bash "collide still -o scenes/" scenes/carts.toml
offer collide still --at '' && expect_only bash "collide still --at " ""
offer collide still --at 2 wor && expect_only bash "collide still --at 2 wor" worked-example

declare -A help_of=()
# The fixed value lists in the scripts must be what --help says the options take.
for option_values in "still --theme light dark high-contrast" "still --backend osmesa egl gpu auto" \
  "still --chart energy momentum force none" "render --format mp4 webm gif frames" \
  "render --preset ultrafast superfast veryfast faster fast medium slow slower veryslow"; do
  read -r command option values <<<"$option_values"
  [[ -n ${help_of[$command]:-} ]] || help_of[$command]=$(collide "$command" --help)
  line=$(grep -E "^  $option " <<<"${help_of[$command]}") || fail "collide $command --help has no $option"
  for value in $values; do
    [[ $line == *"$value"* ]] || fail "collide $command --help does not list '$value' for $option: $line"
    grep -q "$value" "$source_dir/completions/_collide" || fail "the zsh script lacks '$value' for $option"
  done
  offer collide "$command" "$option" '' && expect bash "collide $command $option " $values
done

# --- zsh ---
command -v zsh >"$tmp/zsh-path" || fail "zsh is not installed (scripts/install-packages installs it)"
zsh -n "$source_dir/completions/_collide" || fail "zsh: _collide does not parse"
# zsh, in one process: each argument is one command line as typed (zsh quoting, '' for an empty
# word being completed); for each, "== LINE" and then what is offered, one per line.
zsh_offers=$(zsh -f -c '
  _describe() { local -a offered; offered=("${(@P)4}"); print -rl -- "${(@)offered%%:*}"; }
  _values() { shift; print -rl -- "$@"; }
  _files() { print -r -- "FILES $*"; }
  compdef() { :; }
  source "$1"; shift
  for typed in "$@"; do
    print -r -- "== $typed"
    words=("${(@Q)${(z)typed}}"); CURRENT=$#words
    _collide
  done' zsh "$source_dir/completions/_collide" "collide ''" "collide still --the" "collide still ''" \
  "collide presets show ''" "collide still --theme ''" "collide still -o ''")
zsh_got() {  # got = what zsh offered for the typed line $1
  got=$(awk -v want="== $1" '$0 == want { on = 1; next } /^== / { on = 0 } on' <<<"$zsh_offers")
}
zsh_got "collide ''" && expect zsh "collide " render still strobe chart data presets check batch info
zsh_got "collide still --the" && expect zsh "collide still --the" --theme
zsh_got "collide still ''" && expect zsh "collide still " "${presets[@]}" "FILES -g *.toml(-.)"
zsh_got "collide presets show ''" && expect zsh "collide presets show " "${presets[@]}"
zsh_got "collide still --theme ''" && expect zsh "collide still --theme " light dark high-contrast
zsh_got "collide still -o ''" && expect zsh "collide still -o " "FILES "
echo "bash and zsh complete commands, options, values, presets and files"
