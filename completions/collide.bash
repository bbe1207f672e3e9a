# bash completion for collide(1): commands, options, option values, preset names and file paths.
# Commands and options are read from the --help of the collide being completed and preset names
# from its `collide presets`, so the completion follows the binary it completes; each answer is
# cached for the shell session. Installed as share/bash-completion/completions/collide.

declare -gA _collide_cache

# _collide_ask KEY COMMAND...: REPLY = COMMAND's output, run once per session and KEY.
_collide_ask() {
  local key=$1
  shift
  if [[ -z ${_collide_cache[$key]+set} ]]; then
    _collide_cache[$key]=$("$@" 2>/dev/null)
  fi
  REPLY=${_collide_cache[$key]}
}

# Subcommands listed by `COLLIDE [COMMAND...] --help`, one per line.
_collide_subcommands() {
  _collide_ask "help $*" "$@" --help
  REPLY=$(awk '/^Subcommands:/ { listing = 1; next }
               listing && /^  [a-z]/ { print $1 }
               /^$/ { listing = 0 }' <<<"$REPLY")
}

# Options of `COLLIDE [COMMAND...]`, one per line: "NAME[ NAME...]<TAB>TYPE" (TYPE empty for a flag).
# CLI11 prints "  -o,--output TEXT REQUIRED   description": the part before the first double space.
_collide_options() {
  _collide_ask "help $*" "$@" --help
  REPLY=$(awk '/^  -/ {
                 spec = substr($0, 3); cut = index(spec, "  "); if (cut) spec = substr(spec, 1, cut - 1)
                 n = split(spec, field, " ")
                 names = field[1]; gsub(/\{[^}]*\}/, "", names); gsub(/,/, " ", names)
                 print names "\t" (n > 1 ? field[2] : "") }' <<<"$REPLY")
}

# The first positional of `COLLIDE [COMMAND...]` (SCENE, NAME), empty when it takes none.
_collide_positional() {
  _collide_ask "help $*" "$@" --help
  REPLY=$(awk '/^Positionals:/ { listing = 1; next }
               listing && /^  [A-Z]/ { print $1; exit }
               /^$/ { listing = 0 }' <<<"$REPLY")
}

_collide_presets() {
  _collide_ask "presets $1" "$1" presets
  REPLY=$(awk '{ print $1 }' <<<"$REPLY")
}

_collide_files() {
  compopt -o filenames 2>/dev/null
  COMPREPLY+=($(compgen -f -- "$1"))
}

_collide() {
  local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD - 1]}
  local collide=${COMP_WORDS[0]}
  collide=${collide/#\~/${HOME:-}}  # HOME may be unset (env -i) in a shell with set -u
  COMPREPLY=()
  local IFS=$'\n'

  # --opt=value arrives as "--opt" "=" "value" (= is a word break).
  if [[ $cur == "=" ]]; then
    prev=${COMP_WORDS[COMP_CWORD - 1]}
    cur=""
  elif [[ $prev == "=" && $COMP_CWORD -ge 2 ]]; then
    prev=${COMP_WORDS[COMP_CWORD - 2]}
  fi

  # The command path: `still`, `presets show`. A word that is not a subcommand of the path so far
  # (an option's value, a scene) ends it.
  local -a path=()
  local i word
  for ((i = 1; i < COMP_CWORD; i++)); do
    word=${COMP_WORDS[i]}
    [[ $word == -* || $word == "=" ]] && continue
    _collide_subcommands "$collide" "${path[@]}"
    if grep -qxF -- "$word" <<<"$REPLY"; then path+=("$word"); else break; fi
  done

  # The value of an option that takes one.
  if [[ $prev == -* ]]; then
    _collide_options "$collide" "${path[@]}"
    local names type=""
    while IFS=$'\t' read -r names type; do
      [[ " $names " == *" $prev "* ]] && break
      type=""
    done <<<"$REPLY"
    if [[ -n $type ]]; then
      # Options whose values are a fixed list; the help text of each names the same values.
      local values=""
      case $prev in
        --theme) values=$'light\ndark\nhigh-contrast' ;;
        --backend) values=$'osmesa\negl\ngpu\nauto' ;;
        --chart) values=$'energy\nmomentum\nforce\nspeed\nnone' ;;
        --format) values=$'mp4\nwebm\ngif\nframes' ;;
        --preset) values=$'ultrafast\nsuperfast\nveryfast\nfaster\nfast\nmedium\nslow\nslower\nveryslow' ;;
      esac
      if [[ -n $values ]]; then
        COMPREPLY=($(compgen -W "$values" -- "$cur"))
      elif [[ $type == TEXT* ]]; then
        _collide_files "$cur"  # output paths, fonts, CSV and JSON files
      fi
      return 0
    fi
  fi

  if [[ $cur == -* ]]; then
    _collide_options "$collide" "${path[@]}"
    local names
    names=$(cut -f1 <<<"$REPLY" | tr ' ' '\n')
    COMPREPLY=($(compgen -W "$names" -- "$cur"))
    return 0
  fi

  _collide_subcommands "$collide" "${path[@]}"
  if [[ -n $REPLY ]]; then
    COMPREPLY=($(compgen -W "$REPLY" -- "$cur"))
    return 0
  fi

  _collide_positional "$collide" "${path[@]}"
  case $REPLY in
    SCENE)
      _collide_presets "$collide"
      COMPREPLY=($(compgen -W "$REPLY" -- "$cur"))
      _collide_files "$cur"
      ;;
    NAME)  # presets show NAME
      _collide_presets "$collide"
      COMPREPLY=($(compgen -W "$REPLY" -- "$cur"))
      ;;
  esac
  return 0
}

complete -F _collide collide
