#!/usr/bin/env bash
# The catalogue check (scripts/po-check) passes on the repository and fails, naming the entry, on
# a template behind the source and on catalogues with a missing, fuzzy or untranslated message or
# too few plural forms.
set -uo pipefail
root=$1
fixtures=$root/tests/text/po_fixtures
scratch=$(mktemp -d "${TMPDIR:-/tmp}/collide-po-check-test.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
status=0
check() {  # check NAME EXPECTED_RC EXPECTED_TEXT COMMAND...
  local name=$1 want_rc=$2 want_text=$3
  shift 3
  "$@" >"$scratch/out" 2>&1
  local rc=$?
  if [[ $rc -ne $want_rc ]] || ! grep -qF -- "$want_text" "$scratch/out"; then
    echo "FAIL $name: exit $rc (want $want_rc), output lacks '$want_text':" >&2
    cat "$scratch/out" >&2
    status=1
  fi
}

check repository 0 "complete" "$root/scripts/po-check"
check complete 0 "1 catalogue(s) complete" \
  "$root/scripts/po-check" --catalogues "$fixtures/collide.pot" "$fixtures/complete.po"
check fuzzy 1 'fuzzy.po: fuzzy (to review, then remove the fuzzy flag): "energy part"|"lost"' \
  "$root/scripts/po-check" --catalogues "$fixtures/collide.pot" "$fixtures/fuzzy.po"
check untranslated 1 'untranslated.po: untranslated: "Energy against time"' \
  "$root/scripts/po-check" --catalogues "$fixtures/collide.pot" "$fixtures/untranslated.po"
check missing 1 'missing.po: missing (run scripts/update-po): "Energy against time"' \
  "$root/scripts/po-check" --catalogues "$fixtures/collide.pot" "$fixtures/missing.po"
check plural-forms 1 "some messages have only one plural form" \
  "$root/scripts/po-check" --catalogues "$fixtures/collide.pot" "$fixtures/plural_forms.po"

# A marked string added to the source without updating the template.
mkdir -p "$scratch/tree"
cp -r "$root/scripts" "$root/src" "$root/po" "$scratch/tree/"
echo 'static const char* const kNew = N_("A message the template lacks");' \
  >>"$scratch/tree/src/text/wording.cpp"
check template-behind 1 "po/collide.pot is behind the source" "$scratch/tree/scripts/po-check"
exit $status
