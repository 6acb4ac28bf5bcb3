#!/usr/bin/python3
"""tools/plot's 3D profile line (profile_line) on meshes made here, whose line is known:
  1. a 5 x 5 grid of spacing 2 mm in the plane y = 0, opened most at its corner (0, 0, 0):
     the line is the diagonal, its nodes (i, i) at distances 2 sqrt(2) i;
  2. the same grid turned about an oblique axis and moved: the same nodes, the same distances
     (1e-12), whatever the frame;
  3. a disc of radius 10 on a polar grid, opened most at the rim point (10, 0, 0): the nodes
     within half a spacing of the diameter through it, the centre among them, at distances
     |x - 10| from it;
  4. a strip 20 x 2 cells opened at a corner: its whole first row, along its length;
  5. a bore (a closed cylinder about an oblique axis): unrolled (arcs, heights, its period),
     the profile around it through the most opened node's ring;
  6. half a bore unrolled open; a flat grid and a spherical cap are no cylinders;
  7. 2D: a closed circle's profile goes back to its first node, a half circle's and a C's
     whose ends are closer than its spacing do not.
Skipped (77) without numpy and matplotlib.
Usage: check_profile_line.py TOOLS_PLOT"""
import importlib.machinery
import importlib.util
import math
import sys

try:
    import numpy as np
    import matplotlib  # noqa: F401
except ImportError:
    print("skipped: numpy or matplotlib is not installed")
    sys.exit(77)

loader = importlib.machinery.SourceFileLoader("rccm_plot", sys.argv[1])
spec = importlib.util.spec_from_loader("rccm_plot", loader)
plot = importlib.util.module_from_spec(spec)
loader.exec_module(plot)
failed = 0


def check(ok, what):
    global failed
    if not ok:
        failed += 1
        print("FAIL " + what)


def columns(X, u_n, a):
    return {"x [mm]": X[:, 0], "y [mm]": X[:, 1], "z [mm]": X[:, 2], "u_n [mm]": u_n, "a [mm2]": a}


# 1. The grid, opened most at its corner: u_n falls with the distance from it.
i, k = np.meshgrid(np.arange(5), np.arange(5), indexing="ij")
X = np.column_stack([2.0 * i.ravel(), np.zeros(25), 2.0 * k.ravel()])
u_n = 1.0 / (1.0 + np.linalg.norm(X, axis=1))
a = np.full(25, 4.0)
rows, s = plot.profile_line(columns(X, u_n, a))
diagonal = [n for n in range(25) if i.ravel()[n] == k.ravel()[n]]
check(sorted(rows.tolist()) == diagonal, f"grid: rows {sorted(rows.tolist())}, want the diagonal {diagonal}")
check(np.allclose(s, 2 * math.sqrt(2) * i.ravel()[rows], atol=1e-12), f"grid: distances {s}")

# 2. Turned about (1, 2, 3) by 0.7 rad and moved: the same rows and distances.
axis = np.array([1.0, 2.0, 3.0]) / math.sqrt(14.0)
K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
Q = np.eye(3) + math.sin(0.7) * K + (1 - math.cos(0.7)) * K @ K
turned = X @ Q.T + np.array([5.0, -3.0, 7.0])
rows_t, s_t = plot.profile_line(columns(turned, u_n, a))
check(rows_t.tolist() == rows.tolist(), f"turned grid: rows {rows_t.tolist()}, want {rows.tolist()}")
check(np.allclose(s_t, s, atol=1e-12), f"turned grid: distances {s_t}, want {s}")

# 3. A disc: rings of radius 10 j / 5 with 8 j nodes, opened most at (10, 0, 0).
points = [(0.0, 0.0)]
for j in range(1, 6):
    points += [(2.0 * j * math.cos(2 * math.pi * m / (8 * j)), 2.0 * j * math.sin(2 * math.pi * m / (8 * j))) for m in range(8 * j)]
D = np.array([(x, 0.0, z) for x, z in points])
u_n = 1.0 / (1.0 + np.linalg.norm(D - np.array([10.0, 0.0, 0.0]), axis=1))
area = np.full(len(D), math.pi * 100 / len(D))
rows, s = plot.profile_line(columns(D, u_n, area))
spacing = math.sqrt(math.pi * 100 / len(D))
check(0 in rows.tolist(), "disc: the centre is not on the line")
check(len(rows) >= 9, f"disc: {len(rows)} nodes on the line")
check(np.all(np.abs(D[rows, 2]) <= 0.5 * spacing + 1e-12), "disc: a node farther than half a spacing from the diameter")
check(np.allclose(s, 10.0 - D[rows, 0], atol=1e-12), "disc: distances are not 10 - x")
# 4. A strip of 20 x 2 cells of 1 mm, opened most at (0, 0, 0): its line runs along x, the
#    row z = 0 whole (a line to the centroid (10, 0, 1) would leave the row midway).
i, k = np.meshgrid(np.arange(21), np.arange(3), indexing="ij")
S = np.column_stack([1.0 * i.ravel(), np.zeros(i.size), 1.0 * k.ravel()])
u_n = 1.0 / (1.0 + np.linalg.norm(S, axis=1))
a = np.where((i.ravel() % 20 == 0), 0.5, 1.0) * np.where(k.ravel() % 2 == 0, 0.5, 1.0)
rows, s = plot.profile_line(columns(S, u_n, a))
row = [n for n in range(i.size) if k.ravel()[n] == 0]
check(sorted(rows.tolist()) == row, f"strip: rows {sorted(rows.tolist())}, want the row z = 0 {row}")
check(np.allclose(s, S[rows, 0], atol=1e-12), "strip: distances are not x")
# 5. A bore (a closed cylinder of radius 2 about an oblique axis through (1, -2, 3)): 24 nodes
#    around, 5 rings 1 mm apart. Unrolled: arcs 2 pi R / 24 apart, heights along the axis as
#    built, closed (its period the circumference); the profile from the most opened node
#    (angle 0, the middle ring) runs around the surface through that ring, not across the bore.
R, n_around = 2.0, 24
e1 = np.cross(axis, [1.0, 0.0, 0.0])
e1 /= np.linalg.norm(e1)
e2 = np.cross(axis, e1)
th, h = np.meshgrid(2 * math.pi * np.arange(n_around) / n_around, np.arange(5.0), indexing="ij")
th, h = th.ravel(), h.ravel()
B = np.array([1.0, -2.0, 3.0]) + np.outer(R * np.cos(th), e1) + np.outer(R * np.sin(th), e2) + np.outer(h, axis)
uv, names, period = plot.surface_coordinates(B)
check(names == ("around the axis [mm]", "along the axis [mm]"), f"bore: coordinates {names}")
check(period is not None and abs(period - 2 * math.pi * R) < 1e-9, f"bore: period {period}")
step = 2 * math.pi * R / n_around
check(np.allclose(np.diff(np.unique(np.round(uv[:, 0] / step, 9))), 1.0), "bore: arcs not 2 pi R / 24 apart")
check(np.allclose(np.ptp(uv[:, 0]), (n_around - 1) * step), f"bore: arcs span {np.ptp(uv[:, 0])}")
check(np.allclose(uv[:, 1] - h, (uv[:, 1] - h)[0], atol=1e-9), "bore: heights along the axis are not the built ones")
u_n = 1.0 / (1.0 + np.linalg.norm(B - B[2], axis=1))  # node 2: angle 0, height 2
rows, s = plot.profile_line(columns(B, u_n, np.full(len(B), step)))
check(sorted(rows.tolist()) == [n for n in range(len(B)) if h[n] == 2.0], f"bore: rows {sorted(rows.tolist())}, want the ring h = 2")
check(np.allclose(np.diff(np.sort(s)), step) and np.min(np.abs(s)) < 1e-9, f"bore: distances {np.sort(s)}")
# Coarser bores and more rings: still cylinders, still closed (8 around: 45 degrees apart).
for around, rings in ((8, 3), (12, 6), (16, 6), (14, 8)):
    th_c, h_c = np.meshgrid(2 * math.pi * np.arange(around) / around, np.arange(float(rings)), indexing="ij")
    C = np.outer(R * np.cos(th_c.ravel()), e1) + np.outer(R * np.sin(th_c.ravel()), e2) + np.outer(h_c.ravel(), axis)
    _, _, period_c = plot.surface_coordinates(C)
    check(period_c is not None and abs(period_c - 2 * math.pi * R) < 1e-9,
          f"bore of {around} x {rings}: period {period_c}, want {2 * math.pi * R}")
# 6. Half of it (180 degrees): unrolled open (no period), over pi R; a flat grid and a
#    spherical cap are no cylinders.
half = th <= math.pi + 1e-12
uv, _, period = plot.surface_coordinates(B[half])
check(period is None and abs(np.ptp(uv[:, 0]) - math.pi * R) < 1e-9, f"half bore: period {period}, arc {np.ptp(uv[:, 0])}")
check(plot.tube(X) is None, "the flat grid taken for a cylinder")
phi, psi = np.meshgrid(np.linspace(0, 0.8, 6), np.linspace(0, 2 * math.pi, 16, endpoint=False), indexing="ij")
cap = 10 * np.column_stack([(np.sin(phi) * np.cos(psi)).ravel(), np.cos(phi).ravel(), (np.sin(phi) * np.sin(psi)).ravel()])
check(plot.tube(cap) is None, "a spherical cap taken for a cylinder")
# 7. 2D: a fibre's circle (16 nodes, radius 3) is drawn around and back to its first node,
#    over the polygon's perimeter; a half circle stays open.
phi = 2 * math.pi * np.arange(16) / 16
circle = {"x [mm]": 3 * np.cos(phi), "y [mm]": 3 * np.sin(phi), "beta": np.linspace(0.0, 1.0, 16)}
(s, v, _, _), = plot.profile_lines(circle, circle["beta"])
check(len(s) == 17 and abs(s[-1] - 16 * 6 * math.sin(math.pi / 16)) < 1e-12 and v[-1] == v[0],
      f"circle: {len(s)} points to s = {s[-1]}, last value {v[-1]}")
half = {k: np.asarray(val)[:9] for k, val in circle.items()}
(s, v, _, _), = plot.profile_lines(half, half["beta"])
check(len(s) == 9, f"half circle: {len(s)} points, want 9 (open)")
#    With the nodes' lengths of the run's CSV (a [mm]: half of each edge at a node): the
#    circle still closed, and a C whose ends are closer than its spacing (15 edges of 23.5
#    degrees around, a gap of 7.5 degrees) open.
def with_lengths(x, y, closed):
    edges = np.hypot(np.diff(x), np.diff(y))
    ends = math.hypot(x[-1] - x[0], y[-1] - y[0]) if closed else 0.0
    a = (np.append(ends, edges) + np.append(edges, ends)) / 2
    return {"x [mm]": x, "y [mm]": y, "a [mm]": a, "beta": np.linspace(0.0, 1.0, len(x))}
ring = with_lengths(circle["x [mm]"], circle["y [mm]"], True)
(s, v, _, _), = plot.profile_lines(ring, ring["beta"])
check(len(s) == 17 and v[-1] == v[0], f"circle with lengths: {len(s)} points, want 17 (closed)")
psi = np.radians(23.5) * np.arange(16)
c_shape = with_lengths(3 * np.cos(psi), 3 * np.sin(psi), False)
check(math.hypot(c_shape["x [mm]"][-1] - 3, c_shape["y [mm]"][-1]) < 0.5 * 3 * np.radians(23.5), "the C's ends not close")
(s, v, _, _), = plot.profile_lines(c_shape, c_shape["beta"])
check(len(s) == 16, f"C with close ends: {len(s)} points, want 16 (open)")
print(f"{'FAILED' if failed else 'passed'}: {failed} failure(s)")
sys.exit(1 if failed else 0)
