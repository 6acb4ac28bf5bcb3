#!/usr/bin/env bash
# tools/plot draws every figure of a run (skipped, exit 77, when matplotlib is missing):
#  1. it exits 0 on RESULT_DIR (and on each further result directory given, e.g. B2) and
#     writes into RESULT_DIR/plots/ only;
#  2. every expected figure (profiles, deformed, force, history_<W> for each watched point W
#     of history.csv; a 3D run: beta_map instead of deformed) exists as a PNG (200 dpi, 5 to 7 in wide, not blank) and as an SVG;
#  3. it exits non-zero with a message on what is not a result directory (an empty
#     directory, a file, no argument).
# Usage: check_plot.sh RESULT_DIR tools/plot [MORE_RESULT_DIRS...]
set -u
run=$1; plot=$2; shift 2
py=/usr/bin/python3
$py -c "import matplotlib" 2>/dev/null || { echo "skipped: python3-matplotlib is not installed"; exit 77; }
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
passed=0; failed=0
pass() { passed=$((passed + 1)); }
fail() { echo "FAIL $*"; failed=$((failed + 1)); }

# The figures of a run: each a PNG and an SVG fit for a paper. Prints one FAIL line per problem.
check_figures() {
  $py - "$1" <<'EOF'
import csv, os, struct, sys, xml.etree.ElementTree as ET
import matplotlib.image
run = sys.argv[1]
with open(os.path.join(run, "history.csv"), newline="") as f:
    header = next(csv.reader(f))
watched = [k[: -len(" Radh_n [N]")] for k in header if k.endswith(" Radh_n [N]")]
import glob
profiles = sorted(glob.glob(os.path.join(run, "interface_t*.csv")))
solid = bool(profiles) and "z [mm]" in open(profiles[0]).readline()  # 3D: beta over the surface, no deformed figure
# A watched point's name in its figure's file: characters other than letters, digits, . - _
# made _ (README "output.watch"); the second of the same name gets _2.
import re
stems = []
for w in watched:
    stem = re.sub(r"[^A-Za-z0-9._-]", "_", w)[:80].lstrip(".") or "_"
    stems.append(stem if stem not in stems else stem + "_2")
names = ["profiles", "beta_map" if solid else "deformed", "force"] + ["history_" + s for s in stems]
stray = set(os.listdir(os.path.join(run, "plots"))) - {n + e for n in names for e in (".png", ".svg")}
stray = {f for f in stray if not f.startswith(".rccm-plots") and f.startswith("history")}
bad = 0
def fail(msg):
    global bad
    bad += 1
    print(f"FAIL {run}: {msg}")
for name in names:
    png, svg = (os.path.join(run, "plots", f"{name}.{e}") for e in ("png", "svg"))
    try:
        with open(png, "rb") as f:
            data = f.read()
        if data[:8] != b"\x89PNG\r\n\x1a\n":
            raise ValueError("not a PNG")
        width, height = struct.unpack(">II", data[16:24])
        at = data.find(b"pHYs")
        dpi = struct.unpack(">I", data[at + 4:at + 8])[0] * 0.0254 if at > 0 else 0
        if abs(dpi - 200) > 1:
            fail(f"{name}.png at {dpi:.0f} dpi, want 200")
        if not 5 * 200 <= width <= 7 * 200 + 2 or not 300 <= height <= 9 * 200:
            fail(f"{name}.png is {width} x {height} px, want 5-7 in wide at 200 dpi")
        pixels = matplotlib.image.imread(png)
        if pixels[..., :3].std() < 0.02:
            fail(f"{name}.png is blank")
    except (OSError, ValueError) as e:
        fail(f"{name}.png: {e}")
    try:
        root = ET.parse(svg).getroot()
        if not root.tag.endswith("svg") or len(list(root.iter())) < 100:
            fail(f"{name}.svg is not a drawing")
    except (OSError, ET.ParseError) as e:
        fail(f"{name}.svg: {e}")
if stray:
    fail(f"figures of no watched point: {sorted(stray)}")
print(f"{len(names)} figures of {run}: {len(names) * 2} files checked")
sys.exit(1 if bad else 0)
EOF
}

# 1-2. Every run given: exit 0, the figures, nothing written outside plots/.
for dir in "$run" "$@"; do
  rm -rf "$dir/plots"
  before=$(ls -A "$dir")
  if "$plot" "$dir" >"$work/out" 2>"$work/err"; then pass; else fail "$plot $dir: exit $?: $(cat "$work/err")"; continue; fi
  [ "$(ls -A "$dir" | grep -vx plots)" = "$before" ] && pass || fail "$dir: files written outside plots/"
  grep -q "plots in" "$work/out" && pass || fail "$dir: no 'plots in' line"
  if check_figures "$dir"; then pass; else fail "$dir: figures"; fi
done

# 3. Not result directories: refused with a message, nothing written.
mkdir -p "$work/empty"
for bad in "$work/empty" "$run/history.csv" "$work/missing"; do
  if "$plot" "$bad" >/dev/null 2>"$work/err"; then fail "$plot $bad: exit 0 on a non-result directory"
  elif [ ! -s "$work/err" ]; then fail "$plot $bad: no message"
  else pass; fi
done
[ -e "$work/empty/plots" ] && fail "plots written into a non-result directory" || pass
if "$plot" >/dev/null 2>"$work/err"; then fail "$plot without argument: exit 0"; else pass; fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
