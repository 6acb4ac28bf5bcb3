#!/usr/bin/env bash
# How `rccm run` ends when it cannot or must not go on, and what it leaves behind:
#  1. a run that fails (the body comes loose): exit 3, a report saying STOPPED, complete CSV lines;
#  2. SIGINT and SIGTERM: exit 130 / 143 at an accepted step, the files complete up to it;
#  3. a second run into a directory holding results: exit 2 and nothing touched; --force reruns;
#  4. two runs at once into one directory: the second is refused (exit 2).
set -u
rccm=$1; src=$2
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
failed=0
fail() { echo "FAIL $*"; failed=$((failed + 1)); }
# Every line of a CSV has the header's number of fields (no half line).
complete_csv() {
  awk -F, 'NR == 1 { n = NF } NF != n { bad = 1 } END { exit bad }' "$1"
}
slow=(--set 'integrator.rtol=1e-10' --set 'integrator.atol=1e-16')  # B1 for several seconds

# 1. Failure.
out=$work/loose
"$rccm" run "$src/tests/stops/comes_loose.cfg" -q --set "output.directory=\"$out\"" 2>"$work/err"; rc=$?
[ "$rc" -eq 3 ] || fail "failing run: exit $rc, want 3"
grep -q "more than the body's size" "$work/err" || fail "failing run: stderr lacks the reason: $(cat "$work/err")"
grep -q "status: STOPPED" "$out/report.txt" 2>/dev/null || fail "failing run: report.txt does not say STOPPED"
complete_csv "$out/history.csv" || fail "failing run: history.csv has a broken line"

# 2. Signals, sent once the run is under way (its history has a few steps).
for sig in INT TERM; do
  out=$work/$sig
  "$rccm" run "$src/config/b1.cfg" -q "${slow[@]}" --set "output.directory=\"$out\"" 2>"$work/err" &
  pid=$!
  for _ in $(seq 100); do [ -f "$out/history.csv" ] && [ "$(wc -l < "$out/history.csv")" -gt 20 ] && break; sleep 0.1; done
  kill -s "$sig" "$pid"; wait "$pid"; rc=$?
  want=$([ "$sig" = INT ] && echo 130 || echo 143)
  [ "$rc" -eq "$want" ] || fail "SIG$sig: exit $rc, want $want"
  grep -q "status: STOPPED" "$out/report.txt" 2>/dev/null || fail "SIG$sig: report.txt does not say STOPPED"
  complete_csv "$out/history.csv" || fail "SIG$sig: history.csv has a broken line"
  complete_csv "$out/curves.csv" || fail "SIG$sig: curves.csv has a broken line"
  last=$(tail -1 "$out/history.csv" | cut -d, -f1)
  ls "$out"/interface_t"$last".csv >/dev/null 2>&1 || fail "SIG$sig: no interface file at the last step t = $last"
  ls "$out"/*.tmp >/dev/null 2>&1 && fail "SIG$sig: a temporary file was left"
done

# 3. Earlier results are not overwritten by accident.
out=$work/INT
before=$(md5sum "$out/history.csv")
"$rccm" run "$src/config/b1.cfg" -q --set integrator.method=euler --set "output.directory=\"$out\"" 2>"$work/err"; rc=$?
[ "$rc" -eq 2 ] || fail "rerun: exit $rc, want 2"
grep -q -- "--force" "$work/err" || fail "rerun: the message does not mention --force"
[ "$(md5sum "$out/history.csv")" = "$before" ] || fail "rerun: history.csv was touched"
"$rccm" run "$src/config/b1.cfg" -q --force --set integrator.method=euler --set "output.directory=\"$out\"" \
  >/dev/null 2>&1 || fail "rerun with --force failed"
grep -q "status: complete" "$out/report.txt" || fail "rerun with --force: report.txt is not complete"

# 4. Two runs at once.
out=$work/both
"$rccm" run "$src/config/b1.cfg" -q "${slow[@]}" --set "output.directory=\"$out\"" 2>/dev/null &
pid=$!
for _ in $(seq 100); do [ -s "$out/history.csv" ] && break; sleep 0.1; done
"$rccm" run "$src/config/b1.cfg" -q --force --set "output.directory=\"$out\"" 2>"$work/err"; rc=$?
kill -s INT "$pid"; wait "$pid"
[ "$rc" -eq 2 ] || fail "concurrent run: exit $rc, want 2"
grep -q "another rccm run is writing" "$work/err" || fail "concurrent run: $(cat "$work/err")"

echo "$failed failed"
[ "$failed" -eq 0 ]
