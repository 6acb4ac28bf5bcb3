#!/usr/bin/python3
"""tools/plot's beta map of a 3D run draws beta on the interface the run wrote, holes kept:
for every output time of RUN_DIR (an interface with a hole of radius HOLE_RADIUS about the
axis x = z = 0, normal y: tests/meshes/holed-plate.geo),
  1. the map's triangles cover exactly the interface: their areas sum to the sum of the
     contact nodes' tributary areas of the CSV (relative 1e-9); a triangulation of the nodes
     that filled the hole would exceed it by the hole's area;
  2. no triangle lies over the hole (its centroid within HOLE_RADIUS of the axis);
  3. each point of the map carries the beta of the CSV's contact node at its position (1e-12).
Skipped (77) without numpy and matplotlib.
Usage: check_beta_map.py RUN_DIR TOOLS_PLOT HOLE_RADIUS"""
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

run_dir, plot_path, hole = sys.argv[1], sys.argv[2], float(sys.argv[3])
loader = importlib.machinery.SourceFileLoader("rccm_plot", plot_path)
spec = importlib.util.spec_from_loader("rccm_plot", loader)
plot = importlib.util.module_from_spec(spec)
loader.exec_module(plot)

failures = checked = 0


def fail(message):
    global failures
    failures += 1
    print("FAIL", message)


run = plot.Run(run_dir)
paths = glob.glob(os.path.join(run_dir, "interface_t*.csv"))
if not run.surfaces or len(run.surfaces) != len(paths):
    fail(f"{run_dir}: expected a 3D run with {len(paths)} interface CSVs, tools/plot read {len(run.surfaces)}")
for t, c in run.surfaces:
    triangulation, beta, (xi, xj) = plot.beta_map_triangulation(run, t, c)
    if (xi, xj) != ("x [mm]", "z [mm]"):
        fail(f"t = {t}: the map is drawn in ({xi}, {xj}), the interface y = 0 in (x, z)")
    x, z, T = triangulation.x, triangulation.y, triangulation.triangles
    area = 0.5 * np.abs((x[T[:, 1]] - x[T[:, 0]]) * (z[T[:, 2]] - z[T[:, 0]])
                        - (x[T[:, 2]] - x[T[:, 0]]) * (z[T[:, 1]] - z[T[:, 0]]))
    tributary = float(np.sum(c["a [mm2]"]))
    if abs(area.sum() - tributary) > 1e-9 * tributary:
        fail(f"t = {t}: the map's triangles cover {area.sum():.12g} mm2, the interface {tributary:.12g} mm2")
    centroid_r = np.hypot(x[T].mean(axis=1), z[T].mean(axis=1))
    if np.any(centroid_r < hole):
        fail(f"t = {t}: {int(np.sum(centroid_r < hole))} triangles of the map lie over the hole (r < {hole})")
    by_position = {(round(float(a), 9), round(float(b), 9)): float(v)
                   for a, b, v in zip(c["x [mm]"], c["z [mm]"], c["beta"])}
    for a, b, v in zip(x, z, beta):
        key = (round(float(a), 9), round(float(b), 9))
        if key not in by_position or abs(by_position[key] - v) > 1e-12:
            fail(f"t = {t}: the map's point ({a}, {b}) has beta {v}, the CSV {by_position.get(key)}")
            break
    checked += 1
print(f"{checked} maps checked, {failures} failures")
sys.exit(1 if failures or checked == 0 else 0)
