#!/usr/bin/env bash
# The command line as a hostile or hurried user meets it (issue 15):
#  1. malformed --set paths and values are bad input (exit 2, the path named; two settings in
#     one value too, not the first kept and the second dropped), a bare path is a
#     string, -o DIR writes there (a DIR named like a number or "." too), --restart '' is
#     refused, a directory as mesh.file is bad input, a mistyped command is named; a doubtful
#     interface warns;
#  2. alpha = 0 runs the rate-independent limit in `run` as in `sweep`, and in `compare` once
#     with a note; a setting the run's methods do not read is said, not reported as a warning;
#  3. --force starts from an empty result set and leaves other files alone, in plots/ too
#     (its manifest read with CRLF line ends as well), and files and folders named like rccm's;
#  4. a closed pipe (rccm run -v | head) does not kill the run: its files and report are complete;
#  5. a full disk: exit 3, the message names the file that could not be written and does not
#     claim a report that is not there, nor blames the integrator (ARKODE's step callback); the
#     restart once there is room goes on from the last checkpoint whose rows were written;
#  6. SIGINT during a sweep: exit 130, the running case stops at an accepted step, no other
#     case starts, summary.csv says which cases did not run;
#     the same sweep again is refused, its summary untouched, the interrupted case's restart
#     suggested; the command the stopped sweep printed goes on with it (sweep --restart); a
#     sweep's overlay command names its own cases, its cases' notes their case; a sweep into
#     the directory of another is refused, the other's summary untouched;
#  7. a second SIGINT exits at once;
#  8. a signal during a run's set-up exits at once, writing nothing, gmsh's process with it;
#  9. started by a parent that ignores SIGCHLD, a gmsh config still gets its mesh;
# 10. SIGINT to a sweep alone (not its process group) while gmsh meshes its first case: gmsh
#     is stopped with it, at once, not after its meshing.
set -u
rccm=$1; src=$2
work=$(mktemp -d); trap 'umount "$work/full" 2>/dev/null; rm -rf "$work"' EXIT
failed=0; checks=0
fail() { echo "FAIL $*"; failed=$((failed + 1)); }
check() { checks=$((checks + 1)); }
b1="$src/config/b1.cfg"
short=(--set time.T=0.5 --set 'output.times=[0.25]' --set integrator.method=euler --set time.steps=20)

# 1. --set paths and values.
expect_bad() {  # expect_bad "message" args...
  local msg=$1; shift; check
  "$rccm" run "$b1" -q "${short[@]}" "$@" -o "$work/never" 2>"$work/err" >/dev/null; local rc=$?
  [ "$rc" -eq 2 ] || fail "$*: exit $rc, want 2 ($(cat "$work/err"))"
  grep -qF -- "$msg" "$work/err" || fail "$*: message '$(cat "$work/err")' lacks '$msg'"
  [ -e "$work/never" ] && fail "$*: wrote $work/never" && rm -rf "$work/never"
}
expect_bad "--set mesh..nx: '' is not a setting name" --set mesh..nx=3
expect_bad "--set interface.1x: '1x' is not a setting name" --set interface.1x=3
expect_bad "--set interface.m u: 'm u' is not a setting name" --set 'interface.m u=3'
expect_bad "the list has 1 element(s), numbered from 0" --set 'loads.[99999999999999999999].value=1'
expect_bad "--set time.T: the value '0.5;steps=5' holds more than one setting" --set 'time.T=0.5;steps=5'
expect_bad "the integer 100000000000000000000 is beyond what libconfig reads" --set 'loads.[0].value=100000000000000000000'
expect_bad "interface.mu: must be a number (got a string)" --set interface.mu=0.2x
check; "$rccm" run "$b1" -q --restart '' 2>"$work/err"; rc=$?
[ "$rc" -eq 2 ] && grep -q -- "--restart: give the directory" "$work/err" || fail "--restart '': exit $rc, $(cat "$work/err")"

for sub in run sweep; do
  check; (cd "$work" && "$rccm" $sub "$b1" -o '' 2>"$work/err" >/dev/null); rc=$?
  [ "$rc" -eq 2 ] && grep -q -- "-o: give the directory to write in" "$work/err" || fail "$sub -o '': exit $rc, $(cat "$work/err")"
  check; (cd "$work" && "$rccm" $sub "$b1" -o -q 2>"$work/err" >/dev/null); rc=$?
  [ "$rc" -eq 2 ] && grep -q -- "-o -q: a directory name that starts with '-' reads as an option" "$work/err" && [ ! -e "$work/-q" ] \
    || fail "$sub -o -q: exit $rc, $(cat "$work/err")"
done
check; "$rccm" run "$b1" -q "${short[@]}" --set "output.directory=$work/bare path" >/dev/null 2>"$work/err" \
  || fail "a bare path for output.directory: $(cat "$work/err")"
[ -s "$work/bare path/history.csv" ] || fail "a bare path for output.directory: no history.csv there"
check; "$rccm" run "$b1" -q "${short[@]}" -o "$work/dash-o" >/dev/null 2>"$work/err" || fail "-o DIR: $(cat "$work/err")"
[ -s "$work/dash-o/report.txt" ] || fail "-o DIR: no report there"
# -o and --restart take any directory name, one that reads like a number or "." too (they were
# parsed as libconfig values: "-o 2024: output.directory must be a string (got an integer)").
mkdir "$work/cwd"
for dir in 2024 1e3 .; do
  check; (cd "$work/cwd" && "$rccm" run "$b1" -q "${short[@]}" -o "$dir" >/dev/null 2>"$work/err") || fail "-o $dir: $(cat "$work/err")"
  [ -s "$work/cwd/$dir/report.txt" ] || fail "-o $dir: no report there"
done
check; (cd "$work/cwd" && "$rccm" run "$b1" -q "${short[@]}" --restart 2024 >/dev/null 2>"$work/err"); rc=$?
[ "$rc" -eq 2 ] && grep -q "2024/checkpoint.txt: the run reached time.T" "$work/err" || fail "--restart 2024 of a finished run: exit $rc, $(cat "$work/err")"
# A config through a pipe is read once and runs as the file does (it was read twice: "missing
# section 'mesh'"); beyond 16 MiB it is refused, nothing written (/dev/zero was read without end);
# a sweep, which reads its config for every case, refuses a pipe.
check; "$rccm" run "$b1" -q "${short[@]}" -o "$work/from-file" >/dev/null 2>"$work/err" || fail "b1 from its file: $(cat "$work/err")"
check; cat "$b1" | "$rccm" run /dev/stdin -q "${short[@]}" -o "$work/from-pipe" >/dev/null 2>"$work/err" \
  || fail "a config through a pipe: $(cat "$work/err")"
cmp -s "$work/from-file/interface_t0.25.csv" "$work/from-pipe/interface_t0.25.csv" \
  || fail "a config through a pipe: interface_t0.25.csv differs from the file's run"
check; head -c 17000000 /dev/zero | "$rccm" run /dev/stdin -q -o "$work/never" 2>"$work/err" >/dev/null; rc=${PIPESTATUS[1]}
[ "$rc" -eq 2 ] && grep -qF "/dev/stdin: more than 16 MiB, not a config" "$work/err" && [ ! -e "$work/never" ] \
  || fail "17 MB through a pipe: exit $rc, $(cat "$work/err")"
check; cat "$b1" | "$rccm" sweep /dev/stdin --set interface.alpha=1,2 -o "$work/never" 2>"$work/err" >/dev/null; rc=${PIPESTATUS[1]}
[ "$rc" -eq 2 ] && grep -qF "sweep: /dev/stdin is a pipe" "$work/err" && [ ! -e "$work/never" ] \
  || fail "a sweep through a pipe: exit $rc, $(cat "$work/err")"
# A file value the read refuses is refused under the override too (an empty output.directory
# ran under -o).
sed 's|directory = "results/b1";|directory = "";|' "$b1" > "$work/empty-directory.cfg"
check; "$rccm" run "$work/empty-directory.cfg" -q "${short[@]}" -o "$work/never" 2>"$work/err" >/dev/null; rc=$?
[ "$rc" -eq 2 ] && grep -qF "empty-directory.cfg:32: output.directory: must not be empty; --set or -o replaces it" "$work/err" \
  && [ ! -e "$work/never" ] || fail "an empty output.directory under -o: exit $rc, $(cat "$work/err")"
# A mesh.file that is a directory is bad input, named (not an internal error of the file read).
mkdir -p "$work/meshdir/dir.msh"
printf 'mesh = { file = "dir.msh"; };\n' > "$work/meshdir/m.cfg"
check; "$rccm" run "$work/meshdir/m.cfg" -q -o "$work/never" 2>"$work/err" >/dev/null; rc=$?
[ "$rc" -eq 2 ] && grep -qF "m.cfg:1: mesh.file: $work/meshdir/dir.msh is a directory" "$work/err" || fail "a directory as mesh.file: exit $rc, $(cat "$work/err")"
[ -e "$work/never" ] && fail "a directory as mesh.file: wrote $work/never"

# Options out of range say their range in words a user reads (not 1.8e308 written out).
for args in "sweep $b1 --set interface.alpha=1,2 -j 0" "compare $b1 --euler-steps 0" "bench --scale-time 0"; do
  check; "$rccm" $args >/dev/null 2>"$work/err"; rc=$?
  [ "$rc" -eq 2 ] && [ "$(head -1 "$work/err" | wc -c)" -lt 80 ] || fail "$args: exit $rc, $(head -c 300 "$work/err")"
done
# A table that could not be kept is refused before the minutes of the benchmark (timed out if not).
check; timeout 10 "$rccm" bench --csv "$work/none/table.csv" >/dev/null 2>"$work/err"; rc=$?
[ "$rc" -eq 2 ] && grep -q "bench --csv $work/none/table.csv: cannot write into '$work/none'" "$work/err" \
  || fail "bench --csv into no directory: exit $rc, $(cat "$work/err")"
check; timeout 10 "$rccm" bench --json "$work" >/dev/null 2>"$work/err"; rc=$?
[ "$rc" -eq 2 ] && grep -q "bench --json $work: a directory, not a file" "$work/err" \
  || fail "bench --json onto a directory: exit $rc, $(cat "$work/err")"
check; "$rccm" run "$src/config" >/dev/null 2>"$work/err"; rc=$?
[ "$rc" -eq 2 ] && grep -q "config: a directory, not a config file" "$work/err" || fail "run DIR: exit $rc, $(cat "$work/err")"
check; "$rccm" runn "$b1" >/dev/null 2>"$work/err"; rc=$?  # a mistyped command: named, the nearest suggested
[ "$rc" -eq 2 ] && grep -q "'runn' is not a command; did you mean 'run'?" "$work/err" || fail "rccm runn: exit $rc, $(cat "$work/err")"
check; "$rccm" --version | grep -Eq '^rccm [0-9]+\.[0-9]+\.[0-9]+$' || fail "rccm --version: $("$rccm" --version)"

# A doubtful interface is run, and said: on stderr and in the report.
check; "$rccm" run "$b1" -q "${short[@]}" --set interface.g0=0.5 -o "$work/gap" >/dev/null 2>"$work/err" || fail "g0 = 0.5: $(cat "$work/err")"
grep -q "rccm: warning: .*start bonded across a gap" "$work/err" || fail "g0 = 0.5 bonded: no warning on stderr ($(cat "$work/err"))"
grep -q "^warning: .*start bonded across a gap" "$work/gap/report.txt" || fail "g0 = 0.5 bonded: no warning in report.txt"
# ... before the first step: a run that then fails (here: three steps allowed) has said it too.
check; "$rccm" run "$b1" -q --set interface.g0=0.5 --set integrator.max_steps=3 -o "$work/gap3" >/dev/null 2>"$work/err"; rc=$?
[ "$rc" -eq 3 ] && grep -q "rccm: note: .*start bonded across a gap" "$work/err" || fail "g0 = 0.5, 3 steps: exit $rc, no note on stderr ($(cat "$work/err"))"
# A failed run restarts with what its message suggests changed (here: more steps), and ends
# as the uninterrupted run of the same problem: the same accepted steps up to where it failed.
"$rccm" run "$b1" -q --set interface.g0=0.5 --set integrator.max_steps=500000 -o "$work/gapT" >/dev/null 2>&1
check; "$rccm" run "$b1" -q --set interface.g0=0.5 --set integrator.max_steps=500000 --restart "$work/gap3" >/dev/null 2>"$work/err"; rc=$?
[ "$rc" -eq 0 ] && grep -q "^status: complete" "$work/gap3/report.txt" \
  && [ "$(head -4 "$work/gap3/history.csv" | cut -d, -f1-2)" = "$(head -4 "$work/gapT/history.csv" | cut -d, -f1-2)" ] \
  || fail "restart with integrator.max_steps raised: exit $rc, $(cat "$work/err")"

# 2. alpha = 0.
check; "$rccm" run "$b1" -q --set integrator.method=euler --set interface.alpha=0 -o "$work/alpha0" >/dev/null 2>"$work/err" \
  || fail "alpha = 0: $(cat "$work/err")"
grep -q "integrator: rate-independent" "$work/alpha0/report.txt" 2>/dev/null || fail "alpha = 0 did not run rate-independent"
# ... but contact-only holds beta at beta0, alpha or not (B1's beta0 = 1: the adhesive springs stay).
check; "$rccm" run "$b1" -q --set integrator.method=contact-only --set interface.alpha=0 -o "$work/held0" >/dev/null 2>"$work/err" \
  && grep -qx "integrator: contact-only (beta held at beta0)" "$work/held0/report.txt" && [ "$(awk -F, 'NR > 1 && $7 != 1' "$work/held0/interface_t10.csv" | wc -l)" = 0 ] \
  || fail "contact-only at alpha = 0: $(cat "$work/err") $(grep integrator: "$work/held0/report.txt")"
# ... and in `compare` once, saying so for the integrators it stands for.
check; "$rccm" compare "$b1" --integrators euler,arkode,contact-only "${short[@]}" --set interface.alpha=0 >"$work/out" 2>"$work/err"; rc=$?
[ "$rc" -eq 0 ] && grep -qF "note: alpha = 0 on every interface: the rate-independent limit runs once for the integrators asked (euler, arkode)" "$work/err" \
  && grep -q "^contact-only, 20 fixed steps" "$work/out" && grep -q "^rate-independent, 20 fixed steps" "$work/out" \
  || fail "compare at alpha = 0: exit $rc, $(cat "$work/err") $(cat "$work/out")"

# ... and a case whose run fails: named with its message, the others compared, exit 3.
check; "$rccm" compare "$b1" --integrators arkode,euler "${short[@]}" --set integrator.max_steps=3 >"$work/out" 2>"$work/err"; rc=$?
[ "$rc" -eq 3 ] && grep -q "^arkode: run failed: ARKODE stopped" "$work/out" && grep -q "^euler, 20 fixed steps" "$work/out" \
  || fail "compare with a failing case: exit $rc, $(cat "$work/out" "$work/err")"

# A setting the run's methods do not read: said before the first step, not a warning of the report.
check; "$rccm" run "$b1" -q "${short[@]}" --set integrator.rtol=1e-7 -o "$work/unread" >/dev/null 2>"$work/err"; rc=$?
[ "$rc" -eq 0 ] && grep -qF 'note: --set integrator.rtol: not read by the "euler" integrator, only by "arkode"' "$work/err" \
  && ! grep -q "not read by" "$work/unread/report.txt" "$work/unread/report.json" || fail "a setting not read: exit $rc, $(cat "$work/err")"

# 3. --force: an empty result set, other files kept.
out=$work/forced
"$rccm" run "$b1" -q "${short[@]}" -o "$out" >/dev/null 2>&1
echo "my notes" > "$out/notes.txt"
MPLBACKEND=Agg "$src/tools/plot" "$out" >/dev/null 2>&1 || fail "tools/plot on $out"
[ -e "$out/plots/profiles.png" ] || fail "tools/plot wrote no plots/profiles.png"
echo "my figure" > "$out/plots/mine.txt"
check; "$rccm" run "$b1" -q --force "${short[@]}" --set 'output.times=[0.3]' -o "$out" >/dev/null 2>"$work/err" \
  || fail "--force: $(cat "$work/err")"
[ -e "$out/interface_t0.25.csv" ] && fail "--force: the earlier run's interface_t0.25.csv is still there"
[ -e "$out/interface_t0.3.csv" ] || fail "--force: no interface_t0.3.csv"
[ "$(ls "$out"/mesh_*.vtu | wc -l)" -eq "$(grep -c '<DataSet' "$out/results.pvd")" ] || fail "--force: .vtu files of the earlier run left"
[ -e "$out/notes.txt" ] || fail "--force removed a file rccm did not write"
[ -e "$out/plots/mine.txt" ] || fail "--force removed the user's file in plots/"
[ -e "$out/plots/profiles.png" ] && fail "--force left the earlier run's plots/profiles.png"
rm "$out/plots/mine.txt"
check; "$rccm" run "$b1" -q --force "${short[@]}" -o "$out" >/dev/null 2>"$work/err" || fail "--force: $(cat "$work/err")"
MPLBACKEND=Agg "$src/tools/plot" "$out" >/dev/null 2>&1 || fail "tools/plot on $out"
sed -i 's/$/\r/' "$out/plots/.rccm-plots"   # the results copied through another system: CRLF line ends
check; "$rccm" run "$b1" -q --force "${short[@]}" -o "$out" >/dev/null 2>"$work/err" || fail "--force: $(cat "$work/err")"
[ -e "$out/plots" ] && fail "--force left plots/ with only tools/plot's files in it: $(ls -A "$out/plots")"
# ... rccm's own files are the names it writes, regular files: a user's files and folders
# named like them stay (mesh_coarse.vtu is no frame, notes.tmp no temporary of rccm's).
mine=(mesh_coarse.vtu mesh_12.vtu interface_thickness.csv interface_threshold.vtp interface_t0.25.csv.bak notes.tmp
      history.csv.bak old.tmp/a.txt)
for f in "${mine[@]}"; do mkdir -p "$(dirname "$out/$f")"; echo mine > "$out/$f"; done
# A folder bearing the name of a file rccm writes would fail the run where it writes it:
# refused before the run (exit 2), everything left as it was.
for folder in mesh_0099.vtu/a.txt interface_t0.9.csv/a.txt interface_0098.vtp; do
  mkdir -p "$out/$folder"
  check; "$rccm" run "$b1" -q --force "${short[@]}" -o "$out" >/dev/null 2>"$work/err"; rc=$?
  [ "$rc" -eq 2 ] && grep -q "is not a file but has the name of one rccm writes there" "$work/err" ||
    fail "--force beside a folder $folder: exit $rc ($(cat "$work/err"))"
  [ -e "$out/history.csv" ] && [ -d "$out/$folder" ] || fail "--force beside a folder $folder: files changed"
  rm -rf "${out:?}/${folder%%/*}"
done
stale=(mesh_0042.vtu interface_0042.vtp mesh_10000.vtu interface_t0.2.csv interface_t1e-05.csv
       history.csv.tmp report.json.tmp mesh_0042.vtu.tmp interface_t0.2.csv.tmp)  # as an earlier run (killed) leaves them
for f in "${stale[@]}"; do echo stale > "$out/$f"; done
check; "$rccm" run "$b1" -q --force "${short[@]}" -o "$out" >/dev/null 2>"$work/err" || fail "--force among a user's files: $(cat "$work/err")"
for f in "${mine[@]}"; do [ "$(cat "$out/$f" 2>/dev/null)" = mine ] || fail "--force removed the user's $f"; done
for f in "${stale[@]}"; do [ -e "$out/$f" ] && fail "--force left the earlier run's $f"; done

# 4. A closed pipe.
out=$work/pipe
check; "$rccm" run "$b1" -v "${short[@]}" -o "$out" 2>"$work/err" | head -2 >/dev/null
rc=${PIPESTATUS[0]}
[ "$rc" -eq 0 ] || fail "rccm run -v | head: exit $rc, want 0 ($(cat "$work/err"))"
grep -q "status: complete" "$out/report.txt" 2>/dev/null || fail "rccm run -v | head: report.txt not complete"

# 5. A full disk (a 96 kB tmpfs; skipped where it cannot be mounted).
mkdir -p "$work/full"
if mount -t tmpfs -o size=96k tmpfs "$work/full" 2>/dev/null; then
  check; "$rccm" run "$b1" -q --set integrator.method=euler --set time.steps=2000 -o "$work/full/run" >/dev/null 2>"$work/err"; rc=$?
  [ "$rc" -eq 3 ] || fail "disk full: exit $rc, want 3"
  grep -q "No space left on device" "$work/err" || fail "disk full: the message does not say why: $(cat "$work/err")"
  if grep -q "report.txt says" "$work/err"; then
    grep -q "status: STOPPED" "$work/full/run/report.txt" 2>/dev/null || fail "disk full: the message claims a report that is not there"
  fi
  # ... and with ARKODE, whose step callback the write fails in: the file named, no integrator's advice.
  rm -rf "$work/full/run"
  check; "$rccm" run "$b1" -q -o "$work/full/run" >/dev/null 2>"$work/err"; rc=$?
  [ "$rc" -eq 3 ] && grep -qE "cannot (write|append to) .*\(No space left on device\)" "$work/err" && ! grep -q "ARKODE" "$work/err" \
    || fail "disk full under ARKODE: exit $rc, $(cat "$work/err")"
  # ... and once there is room again, the restart goes on from the last checkpoint whose rows
  # were written (not from the step whose rows failed: the CSVs would end before it).
  mount -o remount,size=20M "$work/full"
  check; "$rccm" run "$b1" -q --restart "$work/full/run" >/dev/null 2>"$work/err"; rc=$?
  [ "$rc" -eq 0 ] && grep -q "status: complete" "$work/full/run/report.txt" || fail "restart after a full disk: exit $rc, $(cat "$work/err")"
  umount "$work/full"
else
  echo "note: the full-disk case is skipped (no tmpfs mount here)"
fi

# ... and a file size limit (no mount needed): a CSV row fails while the checkpoint, small, could
# still be written. The stop keeps the last checkpoint whose rows were written, so that the
# restart, with the limit gone, goes on (a checkpoint at the failed step: the CSVs end before it).
check; (trap '' XFSZ; ulimit -f 40; exec "$rccm" run "$b1" -q --set output.checkpoint_steps=10 -o "$work/fsize") >/dev/null 2>"$work/err"; rc=$?
[ "$rc" -eq 3 ] && grep -q "(File too large)" "$work/err" || fail "file size limit: exit $rc, $(cat "$work/err")"
check; "$rccm" run "$b1" -q --set output.checkpoint_steps=10 --restart "$work/fsize" >/dev/null 2>"$work/err"; rc=$?
[ "$rc" -eq 0 ] && grep -q "status: complete" "$work/fsize/report.txt" || fail "restart after a file size limit: exit $rc, $(cat "$work/err")"

# 6. SIGINT during a sweep: the first case stops, no other starts.
out=$work/sweep
"$rccm" sweep "$b1" -j 1 --set integrator.rtol=1e-10 --set interface.alpha=1,2,3 -o "$out" >"$work/sweep.out" 2>&1 &
pid=$!
for _ in $(seq 100); do [ -f "$out/alpha=1/history.csv" ] && [ "$(wc -l < "$out/alpha=1/history.csv")" -gt 20 ] && break; sleep 0.1; done
# ... its job list is there while it runs (a sweep killed halfway leaves it) ...
check; [ "$(wc -l < "$out/jobs.txt" 2>/dev/null)" = 3 ] || fail "sweep: no jobs.txt while the cases run"
# ... a second sweep into its directory meanwhile is refused (one sweep at a time there) ...
"$rccm" sweep "$b1" -j 1 --set integrator.rtol=1e-10 --set interface.alpha=1,2,3 --restart "$out" >/dev/null 2>"$work/err"; rc=$?
check; [ "$rc" -eq 2 ] && grep -q "sweep --restart: another rccm run is writing into '$out' now" "$work/err" \
  || fail "a second sweep at once: exit $rc, $(cat "$work/err")"
kill -s INT "$pid"; wait "$pid"; rc=$?
check; [ "$rc" -eq 130 ] || fail "sweep SIGINT: exit $rc, want 130"
[ -e "$out/alpha=2" ] && fail "sweep SIGINT: the next case started"
grep -q '^alpha=1,1,interrupted' "$out/summary.csv" || fail "sweep SIGINT: summary.csv lacks the interrupted case"
grep -q '^alpha=2,2,not run' "$out/summary.csv" || fail "sweep SIGINT: summary.csv lacks the case not run"
check; grep "plots: tools/plot --overlay" "$work/sweep.out" | grep -q "alpha=1" && ! grep "plots: tools/plot --overlay" "$work/sweep.out" | grep -q "alpha=2" \
  || fail "sweep SIGINT: the overlay command names a case not run: $(grep plots: "$work/sweep.out")"

# ... and the same sweep again into its directory: refused (exit 2) naming the case, the
# interrupted case's --restart suggested, summary.csv untouched.
cp "$out/summary.csv" "$work/summary.before"
"$rccm" sweep "$b1" -j 1 --set integrator.rtol=1e-10 --set interface.alpha=1,2,3 -o "$out" >/dev/null 2>"$work/err"; rc=$?
check; [ "$rc" -eq 2 ] && grep -q "sweep: case alpha=1: the sweep's directory $out: '$out/alpha=1' already holds the results of a run (history.csv); give --restart $out/alpha=1 to go on with it" "$work/err" \
  || fail "sweep again: exit $rc, $(cat "$work/err")"
cmp -s "$out/summary.csv" "$work/summary.before" || fail "sweep again: summary.csv changed"
grep -q -- "(--restart $out goes on with the sweep" "$work/err" || fail "sweep again: no --restart of the sweep suggested: $(cat "$work/err")"
# ... and the command the stopped sweep printed goes on with it: the interrupted case from its
# checkpoint, the others run, every row complete.
resume=$(sed -n 's/^rccm: sweep stopped by a signal.*; to go on: //p' "$work/sweep.out")
eval "$resume" >"$work/resume.out" 2>&1; rc=$?
check; [ "$rc" -eq 0 ] && grep -q "^# alpha=1: goes on from its checkpoint at t = " "$work/resume.out" \
  && [ "$(grep -c ',complete,' "$out/summary.csv")" = 3 ] || fail "sweep --restart: exit $rc, command '$resume', $(cat "$work/resume.out")"
# A sweep's cases say whose their notes are (they run at once and mix on stderr).
"$rccm" sweep "$b1" "${short[@]}" --set interface.alpha=1,2 --set 'interface.normal=[0.1,1.0]' -o "$work/swn" >/dev/null 2>"$work/err"
check; grep -q "^rccm: alpha=1: note: .*interface.normal: .* is 5.71 degrees from the boundary's inward normal" "$work/err" \
  && grep -q "^rccm: alpha=2: note: " "$work/err" || fail "sweep notes without their case: $(cat "$work/err")"
# A finished run's directory suggests no restart; a sweep's overlay command names its own cases.
"$rccm" sweep "$b1" -j 1 "${short[@]}" --set interface.alpha=1,2 -o "$work/sw2" >"$work/sw2.out" 2>&1 || fail "sweep sw2: $(cat "$work/sw2.out")"
check; grep -q "plots: tools/plot --overlay '$work/sw2' '$work/sw2/alpha=1' '$work/sw2/alpha=2'$" "$work/sw2.out" || fail "sweep overlay command: $(tail -1 "$work/sw2.out")"
"$rccm" run "$b1" -q "${short[@]}" --set interface.alpha=1 -o "$work/sw2/alpha=1" >/dev/null 2>"$work/err"; rc=$?
check; [ "$rc" -eq 2 ] && ! grep -q -- "--restart" "$work/err" && grep -q "^rccm: error: -o: '$work/sw2/alpha=1' already holds" "$work/err" \
  && grep -q "give --force to overwrite them, or another directory (-o DIR)" "$work/err" \
  || fail "a finished run's directory: exit $rc, $(cat "$work/err")"
# Another sweep into that directory, of other cases: refused, the earlier summary untouched.
cp "$work/sw2/summary.csv" "$work/summary.before"
"$rccm" sweep "$b1" -j 1 "${short[@]}" --set interface.alpha=3,4 -o "$work/sw2" >/dev/null 2>"$work/err"; rc=$?
check; [ "$rc" -eq 2 ] && grep -q "holds the summary.csv of an earlier sweep" "$work/err" && [ ! -e "$work/sw2/alpha=3" ] \
  && cmp -s "$work/sw2/summary.csv" "$work/summary.before" || fail "a sweep over an earlier one: exit $rc, $(cat "$work/err")"
# ... and with --force: the earlier summary goes before the cases run (not left beside the new job list).
"$rccm" sweep "$b1" -j 1 --set integrator.rtol=1e-10 --set interface.alpha=5,6 --force -o "$work/sw2" >/dev/null 2>&1 &
pid=$!
for _ in $(seq 100); do [ -f "$work/sw2/alpha=5/history.csv" ] && break; sleep 0.1; done
check; [ -e "$work/sw2/summary.csv" ] && fail "sweep --force: the earlier summary.csv still there while the cases run"
kill -s INT "$pid"; wait "$pid"
# A sweep of output.directory would run its cases alike, each in DIR/<case>: refused, nothing written.
"$rccm" sweep "$b1" -j 1 "${short[@]}" --set output.directory=x1,x2 -o "$work/swdir" >/dev/null 2>"$work/err"; rc=$?
check; [ "$rc" -eq 2 ] && grep -q "sweep: --set output.directory cannot be swept: the sweep decides each case's directory" "$work/err" \
  && [ ! -e "$work/swdir" ] && [ ! -e x1 ] || fail "a sweep of output.directory: exit $rc, $(cat "$work/err")"
# A case whose directory name would be longer than a file system allows (255 bytes): refused
# before any case runs, the setting named (it failed, and the sweep ended in an internal error).
"$rccm" sweep "$b1" -j 1 "${short[@]}" --set "interface.alpha=0.1,0.$(printf '1%.0s' $(seq 280))" -o "$work/swlong" >/dev/null 2>"$work/err"; rc=$?
check; [ "$rc" -eq 2 ] && grep -q "sweep: --set interface.alpha=0.111.*(282 characters): its case's directory name would be 288 bytes" "$work/err" \
  && [ ! -e "$work/swlong" ] || fail "a sweep with a case directory name too long: exit $rc, $(head -c 400 "$work/err")"
# A sweep none of whose cases has results prints no overlay command that would plot nothing.
"$rccm" sweep "$b1" -j 1 "${short[@]}" --set interface.boundary=nowhere,nothere -o "$work/sw3" >"$work/out" 2>&1; rc=$?
check; [ "$rc" -eq 3 ] && grep -q "plots: none (no case has results)" "$work/out" || fail "a sweep without results: exit $rc, $(cat "$work/out")"

# 7. A second SIGINT: at once, without waiting for the step (B1 refined 16 times: steps of ~0.1 s).
out=$work/twice
"$rccm" run "$b1" -q --set mesh.nx=512 --set mesh.ny=32 -o "$out" >/dev/null 2>&1 &
pid=$!
for _ in $(seq 200); do [ -s "$out/history.csv" ] && break; sleep 0.1; done
kill -s INT "$pid"; kill -s INT "$pid"; wait "$pid"; rc=$?
check; [ "$rc" -eq 130 ] || fail "second SIGINT: exit $rc, want 130"

# 8. A signal during a run's set-up (B1 refined 64 times: its set-up takes minutes) ends it at
# once, writing nothing; gmsh meshing in its own process (a fine disc peel) ends with it.
start=$(date +%s)
timeout --preserve-status -k 15 -s INT 2 "$rccm" run "$b1" -q --set mesh.nx=2048 --set mesh.ny=128 -o "$work/setup" >/dev/null 2>"$work/err"; rc=$?
check; [ "$rc" -eq 130 ] && [ "$(grep -c "^rccm: stopped by signal 2 during set-up; nothing was written$" "$work/err")" = 1 ] && [ ! -e "$work/setup" ] \
  && [ $(( $(date +%s) - start )) -lt 30 ] || fail "SIGINT in set-up: exit $rc after $(( $(date +%s) - start )) s, $(cat "$work/err")"
# SIGTERM to rccm alone (not its process group), once gmsh's process meshes: it ends with rccm.
"$rccm" run "$src/config/disc-peel.cfg" -q --set mesh.parameters.h=0.1237 -o "$work/mesh" >/dev/null 2>"$work/err" &
pid=$!; gmsh_pid=
for _ in $(seq 100); do gmsh_pid=$(pgrep -P "$pid" | head -1); [ -n "$gmsh_pid" ] && break; sleep 0.05; done
# the first child reads the file's dimension and ends at once: wait for the one that meshes
sleep 0.5; gmsh_pid=$(pgrep -P "$pid" | head -1)
kill -s TERM "$pid"
for _ in $(seq 150); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done  # not the whole set-up's minutes
kill -0 "$pid" 2>/dev/null && kill -9 "$pid"
wait "$pid"; rc=$?
sleep 0.5
alive=$(ps -o stat= -p "$gmsh_pid" 2>/dev/null | grep -v Z)  # a zombie waits for init to reap it: ended
check; [ "$rc" -eq 143 ] && [ -n "$gmsh_pid" ] && [ ! -e "$work/mesh" ] && [ -z "$alive" ] \
  || fail "SIGTERM while gmsh meshes: exit $rc, gmsh's process '$gmsh_pid' $(ps -o pid,stat,cmd -p "$gmsh_pid" | tail -1) $(cat "$work/err")"
[ -n "$gmsh_pid" ] && kill -9 "$gmsh_pid" 2>/dev/null

# 9. SIGCHLD ignored by the caller (inherited through exec): rccm-gmsh is still waited for.
/usr/bin/python3 -c 'import os, signal, sys; signal.signal(signal.SIGCHLD, signal.SIG_IGN); os.execv(sys.argv[1], sys.argv[1:])' \
  "$rccm" run "$src/config/dcb.cfg" -q --set time.steps=4 --set "output.times=[0.5]" -o "$work/sigchld" >/dev/null 2>"$work/err"; rc=$?
check; [ "$rc" -eq 0 ] && [ -s "$work/sigchld/curves.csv" ] || fail "SIGCHLD ignored by the caller: exit $rc, $(cat "$work/err")"

# 10. SIGINT to the sweep alone while gmsh meshes a fine disc peel (tens of seconds of meshing).
"$rccm" sweep "$src/config/disc-peel.cfg" --set mesh.parameters.h=0.1237,0.13 -j 2 -o "$work/sweep_mesh" >/dev/null 2>"$work/err" &
pid=$!; gmsh_pid=
for _ in $(seq 100); do gmsh_pid=$(pgrep -f "rccm-gmsh $pid .* mesh " | head -1); [ -n "$gmsh_pid" ] && break; sleep 0.05; done
start=$(date +%s)
kill -s INT "$pid"
for _ in $(seq 150); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
kill -0 "$pid" 2>/dev/null && kill -9 "$pid"
wait "$pid"; rc=$?
check; [ "$rc" -eq 130 ] && [ -n "$gmsh_pid" ] && [ $(( $(date +%s) - start )) -lt 5 ] && ! kill -0 "$gmsh_pid" 2>/dev/null \
  && grep -q '^h=0.1237,0.1237,interrupted' "$work/sweep_mesh/summary.csv" \
  || fail "SIGINT to a sweep while gmsh meshes: exit $rc after $(( $(date +%s) - start )) s, gmsh '$gmsh_pid', $(cat "$work/err")"
[ -n "$gmsh_pid" ] && kill -9 "$gmsh_pid" 2>/dev/null

echo "$((checks - failed)) passed, $failed failed"
[ "$failed" -eq 0 ]
