#!/usr/bin/python3
"""The shipped two-body 3D example (config/coating3d.cfg: a coating strip glued on a
substrate, both hexahedra, the coating's end face lifted in y, the substrate's base held),
checked on its results RUN_DIR by what must hold for any right program:
  1. the coating is held by the interface alone: at each output time the interface's forces
     balance the lift, sum r_n = -F (relative 1e-8 of the largest force), sum r_t1 = sum r_t2
     = 0; the whole is held by the base: its reaction F_y = -F at every step, F_x = F_z = 0;
  2. geometry and load are symmetric about the mid-plane z = W/2: so is beta (1e-9);
  3. beta never grows at a node from one output time to the next; the debonded area never
     shrinks (curves.csv); the energy balance closes (1e-3 of the external work);
  4. tools/plot's force figure leaves out the base's x and z reactions, which stay at
     round-off, and names them in its title; tiny displacements are drawn in 10^k mm.
Skipped (77) without numpy and matplotlib.
Usage: check_coating3d.py RUN_DIR TOOLS_PLOT"""
import csv
import glob
import importlib.machinery
import importlib.util
import os
import sys

try:
    import numpy as np
    import matplotlib  # noqa: F401
except ImportError:
    print("skipped: numpy or matplotlib is not installed")
    sys.exit(77)

run_dir, plot_path = sys.argv[1], sys.argv[2]
W = 4.0  # the strip's width (config/coating3d.geo)
failures = checks = 0


def check(ok, message):
    global failures, checks
    checks += 1
    if not ok:
        failures += 1
        print("FAIL", message)


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0] if k not in ("status", "interface")}


curves = read(os.path.join(run_dir, "curves.csv"))
F = curves["L0 coat_end.y force [N]"]
scale = np.max(np.abs(F))
check(scale > 1, f"the lift's largest force is {scale} N: no load reached the interface")
check(np.max(np.abs(curves["L2 sub_base.y force [N]"] + F)) <= 1e-8 * scale, "the base's F_y is not -F")
for k in ("L1 sub_base.x force [N]", "L3 sub_base.z force [N]"):
    check(np.max(np.abs(curves[k])) <= 1e-8 * scale, f"{k} is not 0")
check(np.all(np.diff(curves["debonded area [mm2]"]) >= 0), "the debonded area shrinks")
work = curves["external work [N mm]"][-1]
check(abs(curves["imbalance [N mm]"][-1]) <= 1e-3 * work, "the energy balance does not close")

measured = {"sum r_n + F": 0.0, "mirror": 0.0}  # the largest, relative to the peak force / absolute
previous = None
snapshots = sorted(glob.glob(os.path.join(run_dir, "interface_t*.csv")), key=lambda p: read(p)["t [s]"][0])
check(len(snapshots) >= 3, f"{len(snapshots)} interface CSVs, want t = 0 ... T")
for path in snapshots:
    c = read(path)
    t = c["t [s]"][0]
    row = int(np.argmin(np.abs(curves["t [s]"] - t)))
    measured["sum r_n + F"] = max(measured["sum r_n + F"], abs(c["r_n [N]"].sum() + F[row]) / scale)
    check(abs(c["r_n [N]"].sum() + F[row]) <= 1e-8 * scale, f"t = {t}: sum r_n = {c['r_n [N]'].sum()}, F = {F[row]}")
    for k in ("r_t1 [N]", "r_t2 [N]"):
        check(abs(c[k].sum()) <= 1e-8 * scale, f"t = {t}: sum {k} = {c[k].sum()}")
    beta = {(round(x, 9), round(z, 9)): b for x, z, b in zip(c["x [mm]"], c["z [mm]"], c["beta"])}
    mirror = max(abs(b - beta.get((x, round(W - z, 9)), np.inf)) for (x, z), b in beta.items())
    measured["mirror"] = max(measured["mirror"], mirror)
    check(mirror <= 1e-9, f"t = {t}: beta differs from its mirror image about z = W/2 by {mirror}")
    if previous is not None:
        check(np.all(c["beta"] <= previous + 1e-12), f"t = {t}: beta grew at a node")
    previous = c["beta"]

loader = importlib.machinery.SourceFileLoader("rccm_plot", plot_path)
spec = importlib.util.spec_from_loader("rccm_plot", loader)
plot = importlib.util.module_from_spec(spec)
loader.exec_module(plot)
drawn = {}
plot.save = lambda fig, out_dir, name: drawn.update(fig=fig)  # keep the figure instead of its files
plot.plot_force(plot.Run(run_dir), run_dir)
fig = drawn.get("fig")
check(fig is not None, "no force figure")
if fig is not None:
    titles = [a.get_title(loc="left") for a in fig.axes]
    check(not any("sub_base.x" in s or "sub_base.z" in s for s in titles), f"a round-off reaction is drawn: {titles}")
    check(any("sub_base.y" in s for s in titles), f"the base's F_y is not drawn: {titles}")
    check("round-off" in fig._suptitle.get_text(), "the title does not name the reactions left out")
# Tiny displacements are drawn in units of their decade (the axis' offset text hit its label).
check(plot.decade(np.array([0.0, 5.8e-5])) == -5 and plot.decade(np.array([-0.3])) == 0, "decade()")
print(f"measured: |sum r_n + F| / max |F| {measured['sum r_n + F']:.1e}, beta's mirror difference "
      f"{measured['mirror']:.1e}, relative energy imbalance {abs(curves['imbalance [N mm]'][-1]) / work:.1e}")
print(f"{checks} checks, {failures} failures")
sys.exit(1 if failures else 0)
