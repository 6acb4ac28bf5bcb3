#!/usr/bin/env bash
# Every config of tests/bad/ makes `rccm run` exit with status 2, say the expected message
# on stderr (its place once), and write nothing. Each runs in an empty working directory of
# its own, where a config without output.directory would write results/: whatever an earlier
# run left in the caller's directory cannot answer for it.
set -u
rccm=$1; dir=$2; failed=0; n=0
out=/tmp/rccm_bad_output_must_not_exist
rm -rf "$out"
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
for f in "$dir"/*.cfg; do
  n=$((n + 1)); fail=0
  expect=$(head -1 "$f" | sed 's/^# expect: //')
  msg=$(cd "$work" && "$rccm" run "$f" 2>&1 >/dev/null); rc=$?
  if [ "$rc" -ne 2 ]; then echo "FAIL $f: exit status $rc, want 2"; fail=1; fi
  case "$msg" in *"$expect"*) ;; *) echo "FAIL $f: message '$msg' lacks '$expect'"; fail=1 ;; esac
  # The place once: a message raised inside another layer's handler is not placed twice.
  [ "$(grep -o -F -- "$f:" <<<"$msg" | wc -l)" -le 1 ] || { echo "FAIL $f: the place is given twice in '$msg'"; fail=1; }
  if [ -e "$out" ]; then echo "FAIL $f: wrote $out"; fail=1; rm -rf "$out"; fi
  if [ -n "$(ls -A "$work")" ]; then echo "FAIL $f: wrote $(ls -A "$work") in its working directory"; fail=1; rm -rf "${work:?}"/*; fi
  failed=$((failed + fail))
done
echo "$((n - failed)) passed, $failed failed"
[ "$failed" -eq 0 ]
