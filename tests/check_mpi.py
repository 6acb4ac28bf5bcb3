#!/usr/bin/python3
"""`mpirun -np 2 rccm run` against `rccm run` in one process (issue 18).

  check_mpi.py RCCM_BINARY

Under mpirun every process runs the problem and PETSc's MUMPS shares the body's solves
(docs/PARALLEL.md); process 0 alone writes. Each case runs serially (CHOLMOD) and on two
processes, and their result files are compared with tests/regression/regression.py's rules:
  fixed      B1, explicit Euler-210: every number of the interface, history and curves files
             to 1e-10 of the largest magnitude of its unit (round-off of two factorizations);
  adaptive   B1, ARKODE at rtol 1e-10: a step-size decision flipped by round-off moves beta
             by the global error: within 1e-6, and the same set of files;
  compressed B1 x16 (513 contact pairs: W0 compressed by peeling from blocks of solves),
             explicit Euler in 20 steps: to 1e-8 of each unit's scale (the compression's
             accuracy; its random probes see the two solvers' round-off).
And the two-process run must write exactly the serial run's files, and a bad setting must stop
both processes with exit status 2 and nothing written.
"""
import os, shutil, subprocess, sys, tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "regression"))
import regression  # noqa: E402

ROOT = regression.ROOT
# Open MPI refuses root without these (a container's CI runs as root); --oversubscribe: two
# processes even where fewer cores are counted.
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMPI_MCA_rmaps_base_oversubscribe="1")
MPIRUN = ["mpirun", "-np", "2"]

B1_X16 = ["--set", "mesh.nx=512", "--set", "mesh.ny=32", "--set", "integrator.method=euler", "--set", "time.steps=20"]
CASES = [
    ("b1-euler", "fixed", 1e-10, ["config/b1.cfg", "--set", "integrator.method=euler", "--set", "time.steps=210"]),
    ("b1-arkode", "adaptive", None, ["config/b1.cfg", "--set", "integrator.rtol=1e-10"]),
    ("b1x16-compressed", "fixed", 1e-8, ["config/b1.cfg"] + B1_X16),
]


def run(prefix, binary, args, out, expect=0):
    cmd = prefix + [binary, "run"] + args + ["-q", "-o", out]
    p = subprocess.run(cmd, cwd=ROOT, env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=600)
    if p.returncode != expect:
        sys.exit("check_mpi: %s exited %d, expected %d:\n%s" % (" ".join(cmd), p.returncode, expect, p.stdout))
    return p.stdout


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    binary = os.path.abspath(sys.argv[1])
    failures, report = [], []
    work = tempfile.mkdtemp(prefix="rccm-mpi-")
    try:
        for name, kind, tol, args in CASES:
            serial, parallel = os.path.join(work, name + "-1"), os.path.join(work, name + "-2")
            run([], binary, args, serial)
            run(MPIRUN, binary, args, parallel)
            if sorted(os.listdir(serial)) != sorted(os.listdir(parallel)):
                failures.append("%s: files %s, serially %s" % (name, sorted(os.listdir(parallel)), sorted(os.listdir(serial))))
            largest = [0.0]
            for f in regression.result_files(serial):
                with open(os.path.join(serial, f)) as a, open(os.path.join(parallel, f)) as b:
                    failures += regression.compare(os.path.join(name, f), kind, a.read(), b.read(), largest, tol or 1e-10)
            report.append("%-18s %-8s largest difference %.2g of the tolerance" % (name, kind, largest[0]))
        # A bad setting: both processes stop, exit status 2, nothing written.
        bad = os.path.join(work, "bad")
        run(MPIRUN, binary, ["config/b1.cfg", "--set", "solver.linear=\"cholmod\""], bad, expect=2)
        if os.path.exists(bad):
            failures.append("bad setting: %s was written" % bad)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    print("\n".join(report))
    for f in failures:
        print("  " + f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
