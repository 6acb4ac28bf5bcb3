#!/usr/bin/env bash
# tools/plot --overlay draws the cases of a sweep into one figure (skipped, exit 77, when
# matplotlib is missing):
#  1. given as the user types it, SWEEP_DIR/* (summary.csv and jobs.txt among the arguments):
#     exit 0, OUT_DIR/overlay.png (200 dpi, 7 in wide, not blank) and overlay.svg, a one-line
#     note for each argument that is not a directory;
#  2. given as the sweep prints it, SWEEP_DIR/*/, with an empty directory and a copy of a case
#     whose report says STOPPED added: exit 0, both skipped with a note, OUT_DIR created;
#  3. nothing but non-result arguments, or no run directory at all: exit non-zero with a
#     message, no figure written;
#  4. a case alpha = 0 is labelled rate-independent, without the integrator it did not use;
#  5. its energy panel draws, for alpha = 0, the work released in snap-through (dashed);
#  6. with a support listed before the pull (the sweep's loads), panel (a) draws the pull, the
#     load whose force is largest, and names it; the sweep's summary.csv reports its peak;
#  7. a support whose force exceeds the pull's (one that carries it back): panel (a) draws the
#     driven load (a value other than 0) all the same;
#  8. a load held from the start (a confining pressure) with a larger force: the driven one;
#  9. runs that load different node sets as the same load (a sweep of loads.[1].node_set): each
#     run's pull drawn, the axes naming the load by its index; a run without it noted;
# 10. a 3D run among 2D ones: its debonded area noted and left out of panel (b) (a length's
#     axis), runs watching different points: panel (c) says each run's first.
# Usage: check_overlay.sh SWEEP_DIR tools/plot
set -u
sweep=$1; plot=$2
py=/usr/bin/python3
$py -c "import matplotlib" 2>/dev/null || { echo "skipped: python3-matplotlib is not installed"; exit 77; }
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
passed=0; failed=0
# tools/plot as a module for the checks below (`from plot_module import plot, drawn`): its
# figures kept in `drawn` instead of saved. The path of tools/plot is each script's argv[1].
cat > "$work/plot_module.py" <<'EOF'
import importlib.machinery, importlib.util, sys
loader = importlib.machinery.SourceFileLoader("rccm_plot", sys.argv[1])
plot = importlib.util.module_from_spec(importlib.util.spec_from_loader("rccm_plot", loader))
loader.exec_module(plot)
drawn = {}
plot.save = lambda fig, out_dir, name: drawn.update(fig=fig)
EOF
pass() { passed=$((passed + 1)); }
fail() { echo "FAIL $*"; failed=$((failed + 1)); }

# OUT_DIR/overlay.png and .svg: a PNG at 200 dpi, 7 in wide, not blank; an SVG drawing.
check_overlay() {
  $py - "$1" <<'EOF'
import os, struct, sys, xml.etree.ElementTree as ET
import matplotlib.image
png, svg = (os.path.join(sys.argv[1], f"overlay.{e}") for e in ("png", "svg"))
try:
    with open(png, "rb") as f:
        data = f.read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "overlay.png is not a PNG"
    width, height = struct.unpack(">II", data[16:24])
    at = data.find(b"pHYs")
    dpi = struct.unpack(">I", data[at + 4:at + 8])[0] * 0.0254 if at > 0 else 0
    assert abs(dpi - 200) <= 1, f"overlay.png at {dpi:.0f} dpi, want 200"
    assert 6.5 * 200 <= width <= 7 * 200 + 2 and height >= 3 * 200, f"overlay.png is {width} x {height} px"
    assert matplotlib.image.imread(png)[..., :3].std() > 0.02, "overlay.png is blank"
    root = ET.parse(svg).getroot()
    assert root.tag.endswith("svg") and len(list(root.iter())) > 100, "overlay.svg is not a drawing"
except (OSError, ET.ParseError, AssertionError) as e:
    print(f"FAIL {e}")
    sys.exit(1)
EOF
}

cases=()
for d in "$sweep"/*/; do [ -f "$d/curves.csv" ] && cases+=("${d%/}"); done
[ "${#cases[@]}" -gt 0 ] || { echo "FAIL $sweep holds no case directory"; echo "0 passed, 1 failed"; exit 1; }

# 1. SWEEP_DIR/*: the files of the sweep among the arguments.
rm -f "$sweep/overlay.png" "$sweep/overlay.svg"
all=("$sweep"/*)
if "$plot" --overlay "$sweep" "${all[@]}" >"$work/out" 2>"$work/err"; then pass; else fail "--overlay DIR DIR/*: exit $?: $(cat "$work/err")"; fi
check_overlay "$sweep" && pass || fail "overlay of $sweep/*"
for f in "${all[@]}"; do
  [ -d "$f" ] && continue
  [ "$(grep -c -F "$f" "$work/err")" -eq 1 ] && pass || fail "no one-line note for $f: $(cat "$work/err")"
done

# 2. SWEEP_DIR/*/ plus an empty directory and a case that failed: both skipped with a note.
mkdir -p "$work/empty"
cp -r "${cases[0]}" "$work/stopped"
sed -i 's/^status: .*/status: STOPPED before T = 10 s, at the last accepted step t = 1 s/' "$work/stopped/report.txt"
if [ -f "$work/stopped/report.json" ]; then
  $py -c 'import json, sys; p = sys.argv[1]; r = json.load(open(p)); r["stopped"] = "failed: a test"; r["complete"] = False; json.dump(r, open(p, "w"))' \
    "$work/stopped/report.json"
fi
out=$work/new/out
if "$plot" --overlay "$out" "$sweep"/*/ "$work/empty" "$work/stopped" >"$work/out" 2>"$work/err"; then pass
else fail "--overlay with a failed case: exit $?: $(cat "$work/err")"; fi
check_overlay "$out" && pass || fail "overlay into a new directory"
grep -q -F "$work/empty" "$work/err" && pass || fail "no note for the empty directory: $(cat "$work/err")"
grep -F "$work/stopped" "$work/err" | grep -q -i "stopped\|failed" && pass || fail "no note for the STOPPED case: $(cat "$work/err")"
grep -q "of ${#cases[@]} runs" "$work/out" && pass || fail "not ${#cases[@]} runs drawn: $(cat "$work/out")"

# 3. Nothing to draw: refused with a message, no figure.
refused() {  # the arguments of tools/plot
  if "$plot" "$@" >/dev/null 2>"$work/err"; then fail "$*: exit 0 with nothing to draw"
  elif [ ! -s "$work/err" ]; then fail "$*: no message"
  else pass; fi
}
refused --overlay "$work/none" "$sweep/summary.csv" "$work/empty" "$work/stopped"
refused --overlay "$work/none"
[ -e "$work/none/overlay.png" ] && fail "overlay.png written with nothing to draw" || pass
# OUT_DIR forgotten: the first run is not taken for it (overlay.png written into a run).
refused --overlay "${cases[0]}" "${cases[@]}"
[ -e "${cases[0]}/overlay.png" ] && fail "overlay.png written into a run's directory" || pass

# 4. Legends: alpha = 0 is the rate-independent limit whatever integrator.method says.
if PYTHONPATH="$work" $py - "$plot" <<'EOF'
import sys
from plot_module import plot
zero, one = plot.case_label("method=arkode_alpha=0"), plot.case_label("method=euler_alpha=1")
solver = plot.case_label("method=rccm_alpha=0")  # solver.method: still counts at alpha = 0
ok = "rate-independent" in zero and "arkode" not in zero and "euler" in one and "rate-independent" not in one
ok = ok and "rccm" in solver
print("" if ok else f"labels: {zero!r}, {one!r}, {solver!r}")
sys.exit(0 if ok else 1)
EOF
then pass; else fail "case labels"; fi

# 5. Panel (d): the rate-independent case's energy is the work released in its snap-throughs
#    (curves.csv's imbalance), dashed, named in the title; the viscous cases' is the damage's.
if PYTHONPATH="$work" $py - "$plot" "${cases[@]}" <<'EOF'
import csv, json, os, sys
from plot_module import plot, drawn
plot.overlay("/nonexistent-unused", sys.argv[2:])
energy = [a for a in drawn["fig"].axes if a.get_title(loc="left").startswith("(d)")][0]
problems = []
for d in sys.argv[2:]:
    rows = list(csv.DictReader(open(os.path.join(d, "curves.csv"))))
    independent = "snap_through_and_step_error" in json.load(open(os.path.join(d, "report.json")))["energy"]
    column = "imbalance [N mm]" if independent else "damage dissipation [N mm]"
    want = [float(r[column]) for r in rows]
    style = "--" if independent else "-"
    if not any(l.get_linestyle() == style and list(l.get_ydata()) == want for l in energy.get_lines()):
        problems.append(f"{d}: no {style} line of its {column}")
if "snap-through" not in energy.get_title(loc="left"):
    problems.append("the title does not say what the dashed line is")
print("; ".join(problems))
sys.exit(1 if problems else 0)
EOF
then pass; else fail "panel (d)"; fi

# 6. The load with the largest force, not the first: in panel (a) and in summary.csv.
if PYTHONPATH="$work" $py - "$plot" "$sweep" "${cases[@]}" <<'EOF'
import csv, os, sys
from plot_module import plot, drawn
sweep, cases = sys.argv[2], sys.argv[3:]
plot.overlay("/nonexistent-unused", cases)
force = [a for a in drawn["fig"].axes if a.get_title(loc="left").startswith("(a)")][0]
problems = []
summary = {r["case"]: r for r in csv.DictReader(open(os.path.join(sweep, "summary.csv")))}
column = "peak force L1 top_left.y [N]"
support, largest = 0.0, 0.0
for d in cases:
    rows = list(csv.DictReader(open(os.path.join(d, "curves.csv"))))
    support = max([support] + [abs(float(r["L0 top_right.x force [N]"])) for r in rows])
    pull = [float(r["L1 top_left.y force [N]"]) for r in rows]
    peak = max(map(abs, pull))
    largest = max(largest, peak)
    if not any(list(l.get_ydata()) == pull for l in force.get_lines()):
        problems.append(f"{d}: panel (a) does not draw the pull L1")
    row = summary.get(os.path.basename(d), {})
    if not row.get(column) or abs(abs(float(row[column])) - peak) > 1e-9 * peak:
        problems.append(f"{d}: summary.csv's {column!r} is {row.get(column)!r}, not the pull's peak {peak}")
if not support < 1e-3 * largest:
    problems.append(f"the support reacts with {support} N, the pull with {largest} N: no test of the choice")
if "top_left" not in force.get_ylabel():
    problems.append(f"panel (a)'s force axis is {force.get_ylabel()!r}")
print("; ".join(problems))
sys.exit(1 if problems else 0)
EOF
then pass; else fail "the drawn and summarized load"; fi

# 7. A support that carries the pull back (two bodies, a pile in its soil), here its force made
#    1.5 times the pull's in copies of the cases: panel (a) still draws the driven load.
# 8. A load held from the start (a confining pressure: its value the same nonzero one at every
#    time), its force 3 times the pull's: panel (a) draws the driven load, not the held one.
for variant in carried held; do
if PYTHONPATH="$work" $py - "$plot" "$work/$variant" "$variant" "${cases[@]}" <<'EOF'
import csv, os, shutil, sys
from plot_module import plot, drawn
variant, copies = sys.argv[3], []
for d in sys.argv[4:]:
    copy = os.path.join(sys.argv[2], os.path.basename(d))
    shutil.copytree(d, copy)
    path = os.path.join(copy, "curves.csv")
    rows = list(csv.DictReader(open(path)))
    for r in rows:
        pull = float(r["L1 top_left.y force [N]"])
        r["L0 top_right.x force [N]"] = repr(-1.5 * pull if variant == "carried" else 3 * abs(pull) + 1.0)
        if variant == "held":
            r["L0 top_right.x value [mm]"] = "0.1"
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    copies.append(copy)
plot.overlay("/nonexistent-unused", copies)
force = [a for a in drawn["fig"].axes if a.get_title(loc="left").startswith("(a)")][0]
ok = "top_left" in force.get_ylabel()
print("" if ok else f"{variant}: panel (a)'s force axis is {force.get_ylabel()!r}, not the driven top_left.y")
sys.exit(0 if ok else 1)
EOF
then pass; else fail "a support $variant drawn instead of the pull"; fi
done

# 9. and 10. Copies of the cases: the second's pull renamed L1 upper.y, a third without L1;
#    then the first made 3D (an area instead of a length) and its watched point renamed.
if PYTHONPATH="$work" $py - "$plot" "$work/mixed" "${cases[@]}" <<'EOF'
import contextlib, csv, io, os, shutil, sys
from plot_module import plot, drawn
out, cases = sys.argv[2], sys.argv[3:5]
def copy(d, name, rename, watched_as=None):
    dest = os.path.join(out, name)
    shutil.copytree(d, dest)
    for f in ("curves.csv", "history.csv"):
        path = os.path.join(dest, f)
        rows = list(csv.reader(open(path)))
        rows[0] = [rename(h) for h in rows[0]]
        if f == "history.csv" and watched_as:  # the watched points' columns "W quantity" renamed "W2 quantity"
            points = [h[: -len(" Radh_n [N]")] for h in rows[0] if h.endswith(" Radh_n [N]")]
            rows[0] = [next((watched_as + h[len(w):] for w in points if h.startswith(w + " ")), h) for h in rows[0]]
        keep = [k for k, h in enumerate(rows[0]) if h is not None]
        with open(path, "w", newline="") as fh:
            csv.writer(fh).writerows([[r[k] for k in keep] for r in rows])
    return dest
first = copy(cases[0], "a", lambda h: h)
renamed = copy(cases[1], "b", lambda h: h.replace("L1 top_left.y", "L1 upper.y"))
without = copy(cases[1], "c", lambda h: None if h.startswith("L1 ") else h)
problems = []
def overlay(runs):
    err = io.StringIO()
    with contextlib.redirect_stderr(err):
        plot.overlay("/nonexistent-unused", runs)
    axes = {a.get_title(loc="left")[:3]: a for a in drawn["fig"].axes}
    return axes, err.getvalue()
axes, err = overlay([first, renamed, without])
force = axes["(a)"]
for d, label in ((first, "L1 top_left.y"), (renamed, "L1 upper.y")):
    pull = [float(r[f"{label} force [N]"]) for r in csv.DictReader(open(os.path.join(d, "curves.csv")))]
    if not any(list(l.get_ydata()) == pull for l in force.get_lines()):
        problems.append(f"panel (a) does not draw {d}'s {label}")
if "each run's load L1" not in force.get_ylabel():
    problems.append(f"panel (a)'s force axis is {force.get_ylabel()!r}")
if f"{without}: has no load L1: not drawn in panel (a)" not in err:
    problems.append(f"no note for the run without L1: {err!r}")
# 10. The first run made 3D: plot.Run reads a z column; here its flag and its curves' area.
solid = copy(cases[0], "d", lambda h: h.replace("debonded length [mm]", "debonded area [mm2]"), watched_as="corner")
Run = plot.Run
class Solid(Run):
    def __init__(self, d):
        super().__init__(d)
        self.solid = self.solid or d == solid
plot.Run = Solid
axes, err = overlay([solid, renamed])
if f"{solid}: a 3D run among 2D ones" in err or f"{renamed}: a 2D run among 3D ones" not in err:
    problems.append(f"mixed dimensions: {err!r}")
if len(axes["(b)"].get_lines()) != 1 or "area" not in axes["(b)"].get_ylabel():
    problems.append(f"panel (b): {len(axes['(b)'].get_lines())} lines, axis {axes['(b)'].get_ylabel()!r}")
if "each run's first watched point" not in axes["(c)"].get_title(loc="left"):
    problems.append(f"panel (c)'s title {axes['(c)'].get_title(loc='left')!r}")
print("; ".join(problems))
sys.exit(1 if problems else 0)
EOF
then pass; else fail "runs with different loads, dimensions or watched points"; fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
