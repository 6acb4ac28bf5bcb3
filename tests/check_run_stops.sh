#!/usr/bin/env bash
# How `rccm run` ends when it cannot or must not go on, and what it leaves behind:
#  1. a run that fails (the body comes loose): exit 3, a report saying STOPPED, complete CSV lines;
#  2. SIGINT and SIGTERM: exit 130 / 143 at an accepted step, the files complete up to it;
#  3. a second run into a directory holding results: exit 2 and nothing touched; --force reruns;
#  4. two runs at once into one directory: the second is refused (exit 2);
#  5. a run killed outright (SIGKILL) and restarted from its last checkpoint (--restart) ends
#     with the files of an uninterrupted run (fixed steps: the same numbers to round-off, 1e-9
#     of each column's largest value; the text columns equal).
set -u
rccm=$1; src=$2
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
failed=0
fail() { echo "FAIL $*"; failed=$((failed + 1)); }
# Every line of a CSV has the header's number of fields (no half line).
complete_csv() {
  awk -F, 'NR == 1 { n = NF } NF != n { bad = 1 } END { exit bad }' "$1"
}
# Two CSV files with the same lines, the same text fields, and numbers that agree to
# 1e-9 of each column's largest magnitude.
same_csv() {
  [ "$(wc -l < "$1")" = "$(wc -l < "$2")" ] || return 1
  awk -F, 'NR == FNR { line[FNR] = $0; next }
    { split(line[FNR], a, ",")
      for (i = 1; i <= NF; i++) {
        if ($i !~ /^[-+0-9.eE]+$/) { if ($i != a[i]) bad = 1; continue }
        d = $i - a[i]; d = d < 0 ? -d : d; v = $i < 0 ? -$i : $i
        if (v > big[i]) big[i] = v
        if (d > diff[i]) diff[i] = d
      } }
    END { for (i in diff) if (diff[i] > 1e-9 * big[i]) bad = 1; exit bad }' "$1" "$2"
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
grep -q "^rccm: error: --set output.directory: another rccm run is writing" "$work/err" || fail "concurrent run: $(cat "$work/err")"

# 5. Kill -9 halfway, restart, compare with an uninterrupted run.
euler=(--set integrator.method=euler --set time.steps=20000 --set output.checkpoint_steps=1000)
"$rccm" run "$src/config/b1.cfg" -q "${euler[@]}" --set "output.directory=\"$work/whole\"" 2>/dev/null
"$rccm" run "$src/config/b1.cfg" -q "${euler[@]}" --set "output.directory=\"$work/parts\"" 2>/dev/null &
pid=$!
for _ in $(seq 200); do [ -f "$work/parts/history.csv" ] && [ "$(wc -l < "$work/parts/history.csv")" -gt 8000 ] && break; sleep 0.02; done
kill -s KILL "$pid"; wait "$pid" 2>/dev/null
grep -q "^step " "$work/parts/checkpoint.txt" 2>/dev/null || fail "kill -9: no checkpoint written"
"$rccm" run "$src/config/b1.cfg" -q "${euler[@]}" --restart "$work/parts" >/dev/null 2>"$work/err" \
  || fail "restart: $(cat "$work/err")"
for f in interface_t3.571.csv interface_t5.143.csv interface_t10.csv; do
  same_csv "$work/whole/$f" "$work/parts/$f" || fail "restart: $f differs from the uninterrupted run's"
done
[ "$(wc -l < "$work/whole/history.csv")" = "$(wc -l < "$work/parts/history.csv")" ] \
  || fail "restart: history.csv has $(wc -l < "$work/parts/history.csv") lines, the uninterrupted run's $(wc -l < "$work/whole/history.csv")"
cut -d, -f1-8 "$work/whole/curves.csv" > "$work/a"; cut -d, -f1-8 "$work/parts/curves.csv" > "$work/b"
same_csv "$work/a" "$work/b" || fail "restart: curves.csv (time, load, force, energy terms) differs"
"$rccm" run "$src/config/b1.cfg" -q "${euler[@]}" --set interface.alpha=2.0 --restart "$work/parts" 2>"$work/err"; rc=$?
[ "$rc" -eq 2 ] && grep -q "other settings than .*: interface.alpha differs" "$work/err" || fail "restart with other settings: exit $rc, $(cat "$work/err")"

echo "$failed failed"
[ "$failed" -eq 0 ]
