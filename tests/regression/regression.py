#!/usr/bin/python3
"""Regression of result files against data kept from an earlier version of rccm.

  regression.py generate RCCM_BINARY   runs every case and keeps its CSVs (gzipped) under data/
  regression.py check RCCM_BINARY      runs every case again and compares with data/

The data were generated on main at bcd0d84, before the layered architecture (issue 14), and are
regenerated only on purpose, by a change that alters the physics or the numerics (say so in the
commit). Columns are matched by their header name, so that new columns do not break the check.

What is compared, per kind of case:
  fixed   fixed steps (explicit Euler-210, ARKODE at integrator.fixed_step): interface, history
          and curves files, every number of every line, to 1e-10 of the largest magnitude in the
          file of its unit (a column in mm against the largest displacement, in N mm against the
          largest work, a column without a unit against itself): round-off only, wherever it
          lands (a column of round-off-sized numbers, such as u_n in the shear benchmark B2,
          differs by eps between CPUs and BLAS kernels); columns of solver work, residuals and
          wall time are skipped;
  adaptive  ARKODE with error control: a flip of one step-size decision by round-off moves the
          result by the global error, so beta in the interface files within 1e-6 (absolute), and
          the set of files must be the same;
  amplified  a fixed-step run that amplifies round-off: Euler-210 on B2 is unstable in its last
          phase (README "Integrators of beta": dt C u^2 / alpha reaches 31), where another CPU's BLAS kernel moves
          beta by 3e-7 and Rbar by 4e-8 of its scale: checked as `adaptive`.
  newton  ARKODE at a fixed step: each stage is still solved by Newton to ARKODE's nonlinear
          tolerance (0.1 of the error weights), and round-off of another instruction set (FMA,
          AVX-512 under RCCM_NATIVE) flips an iteration count: B1 built for this machine against
          a generic build gave other contact-solve counts in 102 of 1004 steps, beta 2.1e-8 apart
          at t = 3.571 and 4.0e-7 at t = 10 (the last phase, beta small, amplifies): checked as
          `adaptive`.
"""
import csv, gzip, io, math, os, shutil, subprocess, sys, tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
DATA = os.path.join(HERE, "data")

# name, kind, command (after the binary; {out} is the output directory), config
CASES = [
    ("b1-euler", "fixed", ["run", "config/b1.cfg", "--set", "integrator.method=euler", "--set", "time.steps=210"]),
    ("b2-euler", "amplified", ["run", "config/b2.cfg", "--set", "integrator.method=euler", "--set", "time.steps=210"]),
    ("b2-mild-euler", "fixed", ["run", "config/b2-mild.cfg", "--set", "integrator.method=euler", "--set", "time.steps=210"]),
    ("b1-arkode-fixed", "newton", ["run", "config/b1.cfg", "--set", "integrator.fixed_step=0.01"]),
    ("b2-arkode-fixed", "newton", ["run", "config/b2.cfg", "--set", "integrator.fixed_step=0.01"]),
    ("b2-mild-arkode-fixed", "newton", ["run", "config/b2-mild.cfg", "--set", "integrator.fixed_step=0.01"]),
    ("b1-arkode-rtol", "adaptive", ["run", "config/b1.cfg", "--set", "integrator.rtol=1e-10"]),
    ("b2-arkode-rtol", "adaptive", ["run", "config/b2.cfg", "--set", "integrator.rtol=1e-10"]),
    ("b1-alpha-sweep", "adaptive", ["sweep", "config/b1.cfg", "--set", "interface.alpha=0.1,1,10",
                                    "--set", "integrator.rtol=1e-10", "-j", "2"]),
]

# Columns that count work or round-off, not results.
SKIP = ("contact solves", "sweeps", "residual", "wall", "stick", "slide", "separated", "status", "node")


def run_case(binary, args, out):
    cmd = [binary] + args + (["--output", out] if args[0] == "sweep" else
                             ["-q", "--set", 'output.directory="%s"' % out]) + ["--force"]
    p = subprocess.run(cmd, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if p.returncode != 0:
        sys.exit("regression: %s failed (%d):\n%s" % (" ".join(cmd), p.returncode, p.stdout))


def result_files(out):
    """Relative paths of the CSV results under out (sweep cases in their subdirectories)."""
    files = []
    for d, _, names in os.walk(out):
        for n in names:
            if n.endswith(".csv") and (n.startswith("interface_t") or n in ("history.csv", "curves.csv")):
                files.append(os.path.relpath(os.path.join(d, n), out))
    return sorted(files)


def read_csv(text):
    rows = list(csv.reader(io.StringIO(text)))
    return rows[0], rows[1:]


def numeric(v):
    try:
        return float(v)
    except ValueError:
        return None


def unit_of(column):
    """The unit in a column header, "u_n [mm]" -> "mm"; "" without one."""
    return column[column.rfind("[") + 1:-1] if column.endswith("]") and "[" in column else ""


def compare(name, kind, ref_text, new_text, largest, fixed_tolerance=1e-10):
    """Returns a list of failures, each a line of text; largest[0] becomes the largest difference
    seen relative to its tolerance (0: the compared numbers are identical). `fixed_tolerance`:
    the `fixed` rule's fraction of each unit's scale."""
    ref_head, ref_rows = read_csv(ref_text)
    new_head, new_rows = read_csv(new_text)
    fails = []
    loose = kind != "fixed"  # adaptive, amplified, newton: beta of the interface files, 1e-6
    if loose and not os.path.basename(name).startswith("interface_t"):
        return fails
    if len(ref_rows) != len(new_rows):
        return ["%s: %d lines, expected %d" % (name, len(new_rows), len(ref_rows))]
    if loose:
        columns = [c for c in ref_head if c == "beta"]
        tol_of = lambda col, scale: 1e-6
    else:
        columns = [c for c in ref_head if not any(s in c for s in SKIP)]
        tol_of = lambda col, scale: fixed_tolerance * scale
    unit_scale = {}  # the largest magnitude in the file per unit ("[mm]", "[N]", ...)
    for i, c in enumerate(ref_head):
        if kind == "fixed" and unit_of(c) and not any(s in c for s in SKIP):
            values = [abs(numeric(r[i]) or 0.0) for r in ref_rows]
            unit_scale[unit_of(c)] = max([unit_scale.get(unit_of(c), 0.0)] + values)
    for c in columns:
        if c not in new_head:
            fails.append("%s: column '%s' is missing" % (name, c))
            continue
        i, j = ref_head.index(c), new_head.index(c)
        ref = [numeric(r[i]) for r in ref_rows]
        new = [numeric(r[j]) for r in new_rows]
        if any(v is None for v in ref):
            continue
        scale = max([abs(v) for v in ref] + [unit_scale.get(unit_of(c), 0.0), 1e-300])
        tol = tol_of(c, scale)
        worst, where = 0.0, -1
        for k, (a, b) in enumerate(zip(ref, new)):
            d = abs(a - b) if b is not None and math.isfinite(b) else math.inf
            if d > worst:
                worst, where = d, k
        largest[0] = max(largest[0], worst / tol)
        if worst > tol:
            fails.append("%s: column '%s' differs by %.3g at line %d (tolerance %.3g)" % (name, c, worst, where + 2, tol))
    return fails


def main():
    if len(sys.argv) != 3 or sys.argv[1] not in ("generate", "check"):
        sys.exit(__doc__)
    mode, binary = sys.argv[1], os.path.abspath(sys.argv[2])
    failures, report = [], []
    for name, kind, args in CASES:
        out = tempfile.mkdtemp(prefix="rccm-regression-")
        try:
            run_case(binary, args, out)
            files = result_files(out)
            keep = os.path.join(DATA, name)
            if mode == "generate":
                shutil.rmtree(keep, ignore_errors=True)
                for f in files:
                    os.makedirs(os.path.dirname(os.path.join(keep, f)), exist_ok=True)
                    with open(os.path.join(out, f), "rb") as src, gzip.open(os.path.join(keep, f + ".gz"), "wb") as dst:
                        dst.write(src.read())
                report.append("%-22s %d files kept" % (name, len(files)))
                continue
            kept = sorted(os.path.relpath(os.path.join(d, n), keep)[:-3]
                          for d, _, ns in os.walk(keep) for n in ns if n.endswith(".csv.gz"))
            case_fails, largest = [], [0.0]
            if kept != files:
                case_fails.append("%s: files %s, expected %s" % (name, files, kept))
            for f in kept:
                if f not in files:
                    continue
                with gzip.open(os.path.join(keep, f + ".gz"), "rt") as ref, open(os.path.join(out, f)) as new:
                    case_fails += compare(os.path.join(name, f), kind, ref.read(), new.read(), largest)
            verdict = "DIFFERENT" if case_fails else "identical" if largest[0] == 0 else "ok"
            report.append("%-22s %-8s %2d files: %-9s (largest difference %.2g of the tolerance)"
                          % (name, kind, len(kept), verdict, largest[0]))
            failures += case_fails
        finally:
            shutil.rmtree(out, ignore_errors=True)
    print("\n".join(report))
    for f in failures:
        print("  " + f)
    if mode == "check":
        print("%d passed, %d failed" % (len(CASES) - len({f.split('/')[0] for f in failures}),
                                        len({f.split('/')[0] for f in failures})))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
