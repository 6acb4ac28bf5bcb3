#!/usr/bin/python3
"""`mpirun -np 2 rccm run` against `rccm run` in one process (issue 18).

  check_mpi.py RCCM_BINARY

Under mpirun every process runs the contact problem and PETSc's MUMPS shares the body's solves,
ARKODE's state beta is split among the processes (docs/PARALLEL.md); process 0 alone writes.
Each case runs serially (CHOLMOD) and on two processes, and their result files are compared with
tests/regression/regression.py's rules:
  fixed      B1, explicit Euler-210: every number of the interface, history and curves files
             to 1e-10 of the largest magnitude of its unit (round-off of two factorizations);
  adaptive   B1, ARKODE at rtol 1e-10 (DIRK, also at alpha = 0.01, stiff; and ERK at alpha =
             100): a step-size decision flipped by round-off moves beta by the global error:
             within 1e-6, and the same set of files;
  compressed B1 x16 (513 contact pairs: W0 compressed by peeling from blocks of solves),
             explicit Euler in 20 steps: to 1e-8 of each unit's scale (the compression's
             accuracy; its random probes see the two solvers' round-off).
The ARKODE runs on two processes must hold ARKODE's state distributed (report.json's
beta_slices: two balanced slices of the contact pairs, each process's size as its vector holds
it, which report.txt says too) and make the serial run's contact solves (within
SOLVES_TOLERANCE); the serial runs and the other integrators hold it whole (beta_slices null).
And the two-process run must write exactly the serial run's files, a bad setting must stop
both processes with exit status 2 and nothing written, a run whose body comes loose must fail
with exit status 3 and ARKODE's message as serially, and a signal to one process alone must
stop both at the same accepted step (exit 143, a report saying so, a checkpoint) from which
`--restart` on two processes goes on to the serial run's results.
"""
import json, os, shutil, signal, subprocess, sys, tempfile, time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "regression"))
import regression  # noqa: E402

ROOT = regression.ROOT
# Open MPI refuses root without these (a container's CI runs as root); --oversubscribe: two
# processes even where fewer cores are counted.
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMPI_MCA_rmaps_base_oversubscribe="1")
MPIRUN = ["mpirun", "-np", "2"]

B1_X16 = ["--set", "mesh.nx=512", "--set", "mesh.ny=32", "--set", "integrator.method=euler", "--set", "time.steps=20"]
B1_ARKODE = ["config/b1.cfg", "--set", "integrator.rtol=1e-10"]
# The contact solves of an ARKODE run on two processes against one: the same integration, up to
# step-size decisions that round-off flips (the norms summed in another order, GMRES for KLU):
# B1 0.4 %, B1 at alpha = 0.01 0.5 %, ERK 0.
SOLVES_TOLERANCE = 0.02
# name, rule, fixed tolerance, arguments, whether ARKODE's state is distributed under mpirun
CASES = [
    ("b1-euler", "fixed", 1e-10, ["config/b1.cfg", "--set", "integrator.method=euler", "--set", "time.steps=210"], False),
    ("b1-arkode", "adaptive", None, B1_ARKODE, True),
    # stiff: the Newton matrix's diagonal spans 1 to ~1e6, only its exact inverse solves it at once
    ("b1-arkode-stiff", "adaptive", None, B1_ARKODE + ["--set", "interface.alpha=0.01"], True),
    # ERK: explicit, stable on B1 once alpha = 100 makes the ODE 100 times less stiff
    ("b1-erk", "adaptive", None, B1_ARKODE + ["--set", "integrator.scheme=erk", "--set", "interface.alpha=100"], True),
    ("b1x16-compressed", "fixed", 1e-8, ["config/b1.cfg"] + B1_X16, False),
]


def run(prefix, binary, args, out, expect=0):
    cmd = prefix + [binary, "run"] + args + ["-q", "-o", out]
    p = subprocess.run(cmd, cwd=ROOT, env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=600)
    if p.returncode != expect:
        sys.exit("check_mpi: %s exited %d, expected %d:\n%s" % (" ".join(cmd), p.returncode, expect, p.stdout))
    return p.stdout


def report(out):
    with open(os.path.join(out, "report.json")) as f:
        return json.load(f)


def check_state(name, serial, parallel, distributed):
    """Failures of where ARKODE's state lived, from the two runs' directories."""
    fails = []
    one, two = report(serial), report(parallel)
    if one["beta_slices"] is not None:
        fails.append("%s: serially beta_slices %s, expected null (whole)" % (name, one["beta_slices"]))
    slices, n = two["beta_slices"], two["contact_nodes"]
    if not distributed:
        if slices is not None:
            fails.append("%s: on two processes beta_slices %s, expected null (not ARKODE: whole)" % (name, slices))
        return fails
    if (not slices or slices["processes"] != 2 or slices["pairs"] != n or slices["smallest"] < 1
            or slices["largest"] - slices["smallest"] > 1 or slices["smallest"] + slices["largest"] != n):
        fails.append("%s: beta_slices %s, expected two balanced slices of the %d contact pairs" % (name, slices, n))
        return fails
    with open(os.path.join(parallel, "report.txt")) as f:
        said = "beta (ARKODE's state) distributed over 2 processes: %d to %d contact pairs each, %d in all" % (
            slices["smallest"], slices["largest"], n)
        if said not in f.read():
            fails.append("%s: report.txt does not say '%s'" % (name, said))
    a, b = one["contact_solves"], two["contact_solves"]
    if abs(a - b) > SOLVES_TOLERANCE * a:
        fails.append("%s: %d contact solves on two processes, %d serially (tolerance %g)" % (name, b, a, SOLVES_TOLERANCE))
    return fails


def pid_of_rank(mpirun_pid, rank):
    """The process of an mpirun run's rank `rank` (a descendant of mpirun with that rank in its
    environment), or None."""
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open("/proc/%s/environ" % entry, "rb") as f:
                env = f.read().split(b"\0")
            pid, ancestors = int(entry), []
            while pid > 1 and len(ancestors) < 10:
                with open("/proc/%d/stat" % pid) as f:
                    pid = int(f.read().rsplit(")", 1)[1].split()[1])
                ancestors.append(pid)
        except (OSError, ValueError, IndexError):
            continue
        if mpirun_pid in ancestors and any(("%s=%d" % (v, rank)).encode() in env for v in ("OMPI_COMM_WORLD_RANK", "PMI_RANK")):
            return int(entry)
    return None


def stopped_and_restarted(binary, work, serial):
    """SIGTERM to process 1 alone, once the run is under way: both stop at the same accepted step
    (exit 143, report.txt STOPPED by the signal, a checkpoint); `--restart` on two processes
    goes on to T with the beta of the serial run `serial` (1e-6). Returns the failures."""
    out = os.path.join(work, "stopped")
    cmd = MPIRUN + [binary, "run"] + B1_ARKODE + ["-q", "-o", out]
    p = subprocess.Popen(cmd, cwd=ROOT, env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    history, victim = os.path.join(out, "history.csv"), None
    for _ in range(600):
        if os.path.exists(history):
            with open(history) as f:
                if sum(1 for _ in f) > 20:
                    victim = pid_of_rank(p.pid, 1)
                    break
        time.sleep(0.05)
    if victim is None:
        p.kill()
        p.communicate()
        return ["stop: process 1 of %s not found while it ran" % " ".join(cmd)]
    os.kill(victim, signal.SIGTERM)
    said = p.communicate(timeout=300)[0]
    fails = []
    if p.returncode != 143:
        fails.append("stop: SIGTERM to process 1: exit %d, expected 143:\n%s" % (p.returncode, said))
    try:
        with open(os.path.join(out, "report.txt")) as f:
            text = f.read()
        if "status: STOPPED" not in text or "stopped by signal 15" not in text:
            fails.append("stop: report.txt does not say the run STOPPED by signal 15:\n%s" % text[:1500])
    except OSError:
        fails.append("stop: no report.txt")
    if not os.path.exists(os.path.join(out, "checkpoint.txt")):
        fails.append("stop: no checkpoint.txt")
    if fails:
        return fails
    stopped_at = text.split("at the last accepted step ", 1)[1].split(" s", 1)[0]
    run(MPIRUN, binary, B1_ARKODE + ["--restart", out], out)
    largest = [0.0]
    for f in regression.result_files(serial):
        with open(os.path.join(serial, f)) as a, open(os.path.join(out, f)) as b:
            fails += regression.compare(os.path.join("stopped-restarted", f), "adaptive", a.read(), b.read(), largest)
    print("%-18s SIGTERM to process 1: both stopped at %s s; restarted: largest difference %.2g of the tolerance"
          % ("b1-arkode-stop", stopped_at, largest[0]))
    return fails


def failed_run(binary, work):
    """A run whose body comes loose halfway (ARKODE cuts its steps, its contact solves fail, it
    stops): exit 3 with ARKODE's message and a report saying STOPPED, on two processes as in one.
    Returns the failures."""
    fails = []
    for prefix, tag in (([], "serially"), (MPIRUN, "on two processes")):
        out = os.path.join(work, "loose " + tag)
        said = run(prefix, binary, ["tests/stops/comes_loose_halfway.cfg"], out, expect=3)
        if "rccm: run failed: ARKODE stopped" not in said or "last contact failure" not in said:
            fails.append("failed run %s: not ARKODE's message with the contact failure:\n%s" % (tag, said))
        try:
            with open(os.path.join(out, "report.txt")) as f:
                if "status: STOPPED" not in f.read():
                    fails.append("failed run %s: report.txt does not say STOPPED" % tag)
        except OSError:
            fails.append("failed run %s: no report.txt" % tag)
    return fails


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    binary = os.path.abspath(sys.argv[1])
    failures, report_lines = [], []
    work = tempfile.mkdtemp(prefix="rccm-mpi-")
    try:
        for name, kind, tol, args, distributed in CASES:
            serial, parallel = os.path.join(work, name + "-1"), os.path.join(work, name + "-2")
            run([], binary, args, serial)
            run(MPIRUN, binary, args, parallel)
            if sorted(os.listdir(serial)) != sorted(os.listdir(parallel)):
                failures.append("%s: files %s, serially %s" % (name, sorted(os.listdir(parallel)), sorted(os.listdir(serial))))
            largest = [0.0]
            for f in regression.result_files(serial):
                with open(os.path.join(serial, f)) as a, open(os.path.join(parallel, f)) as b:
                    failures += regression.compare(os.path.join(name, f), kind, a.read(), b.read(), largest, tol or 1e-10)
            failures += check_state(name, serial, parallel, distributed)
            one, two = report(serial), report(parallel)
            report_lines.append("%-18s %-8s largest difference %.2g of the tolerance; %d steps, %d contact solves "
                                "(serially %d, %d); ARKODE's state split %s" % (name, kind, largest[0], two["steps"],
                                two["contact_solves"], one["steps"], one["contact_solves"], two["beta_slices"]))
        # A bad setting: both processes stop, exit status 2, nothing written.
        bad = os.path.join(work, "bad")
        run(MPIRUN, binary, ["config/b1.cfg", "--set", "solver.linear=\"cholmod\""], bad, expect=2)
        if os.path.exists(bad):
            failures.append("bad setting: %s was written" % bad)
        failures += failed_run(binary, work)
        failures += stopped_and_restarted(binary, work, os.path.join(work, "b1-arkode-1"))
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print("\n".join(report_lines))
    for f in failures:
        print("  " + f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
