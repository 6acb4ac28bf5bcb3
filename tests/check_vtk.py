#!/usr/bin/python3
"""Opens every frame of a run with VTK's own XML readers (the binary, zlib-compressed files
ParaView reads) and checks them:
  - results.pvd and interface.pvd list the same times, a frame at t = 0 among them;
  - the bodies: each cell's type matches its number of points; no NaN, no interface field on bulk nodes, stress and strain full symmetric
    tensors with sigma_zz = nu (sigma_xx + sigma_yy) and eps_zz = 0 in plane strain (2D), or
    tetrahedra and hexahedra only and sigma = lambda tr(eps) I + 2 G eps with E (3D: a fourth
    argument);
  - the interface: 2D a chain of lines, 3D a surface of triangles and quads whose areas sum
    to the nodes' tributary areas; beta, u, Rbar equal the
    interface CSV at the output times, each CSV row's `mesh node` is the body's point at the
    row's coordinates, p = r / a, and the global vector r_xyz has the length of
    the local r.
Exit 77 (skipped) when python3-vtk9 is not installed."""
import csv
import math
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np

try:
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError:
    print("skipped: python3-vtk9 is not installed (tools/install-deps --tests installs it)")
    sys.exit(77)

run, nu = sys.argv[1], float(sys.argv[2]) if len(sys.argv) > 2 else 0.333
E = float(sys.argv[3]) if len(sys.argv) > 3 else 6.9e4


def collection(name):
    return [(float(d.get("timestep")), d.get("file")) for d in ET.parse(os.path.join(run, name)).getroot().iter("DataSet")]


def read(reader, name):
    reader.SetFileName(os.path.join(run, name))
    reader.Update()
    return reader.GetOutput()


def arrays(data):
    return {data.GetArrayName(i): vtk_to_numpy(data.GetArray(i)) for i in range(data.GetNumberOfArrays())}


bodies, interface = collection("results.pvd"), collection("interface.pvd")
assert [t for t, _ in bodies] == [t for t, _ in interface], "the two collections list other times"
assert bodies[0][0] == 0.0, "no frame at t = 0"
checked = 0
for (t, vtu), (_, vtp) in zip(bodies, interface):
    grid = read(vtk.vtkXMLUnstructuredGridReader(), vtu)
    assert grid.GetNumberOfPoints() > 0 and grid.GetNumberOfCells() > 0, vtu
    pd, cd = arrays(grid.GetPointData()), arrays(grid.GetCellData())
    assert "beta" not in pd and "status" not in pd, f"{vtu}: interface fields on the bulk nodes"
    for name, a in list(pd.items()) + list(cd.items()):
        assert not any(math.isnan(v) for v in a.ravel()), f"{vtu}: NaN in {name}"
    for name in ("strain", "stress"):
        T = cd[name].reshape(-1, 3, 3)
        assert abs(T - T.transpose(0, 2, 1)).max() <= 1e-12 * max(1.0, abs(T).max()), f"{vtu}: {name} not symmetric"
    S, Eps = cd["stress"].reshape(-1, 3, 3), cd["strain"].reshape(-1, 3, 3)
    points_of = {5: 3, 9: 4, 10: 4, 12: 8}  # VTK_TRIANGLE, VTK_QUAD, VTK_TETRA, VTK_HEXAHEDRON
    for c in range(grid.GetNumberOfCells()):
        kind, points = grid.GetCellType(c), grid.GetCell(c).GetNumberOfPoints()
        assert points_of.get(kind) == points, f"{vtu}: cell {c} of VTK type {kind} has {points} points"
    solid = all(grid.GetCellType(c) in (10, 12) for c in range(grid.GetNumberOfCells()))  # VTK_TETRA, VTK_HEXAHEDRON
    if solid:
        lam, G = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
        trace = Eps[:, 0, 0] + Eps[:, 1, 1] + Eps[:, 2, 2]
        hooke = lam * trace[:, None, None] * np.eye(3) + 2 * G * Eps
        assert abs(S - hooke).max() <= 1e-9 * max(1.0, abs(S).max()), f"{vtu}: stress is not Hooke's of the strain"
    else:
        assert abs(S[:, 2, 2] - nu * (S[:, 0, 0] + S[:, 1, 1])).max() <= 1e-9 * max(1.0, abs(S).max()), "sigma_zz"
        assert abs(Eps[:, 2, 2]).max() == 0.0, "eps_zz of plane strain"

    poly = read(vtk.vtkXMLPolyDataReader(), vtp)
    ip = arrays(poly.GetPointData())
    if solid:
        assert poly.GetNumberOfPolys() > 0 and poly.GetNumberOfLines() == 0, f"{vtp}: the interface is not a surface"
        area = 0.0
        for c in range(poly.GetNumberOfCells()):
            ids = poly.GetCell(c).GetPointIds()
            x = np.array([poly.GetPoint(ids.GetId(k)) for k in range(ids.GetNumberOfIds())])
            assert len(x) in (3, 4), f"{vtp}: a facet of {len(x)} points"
            for k in range(1, len(x) - 1):  # a fan of triangles (the quads of a flat face)
                area += 0.5 * np.linalg.norm(np.cross(x[k] - x[0], x[k + 1] - x[0]))
        assert abs(area - ip["tributary"].sum()) <= 1e-9 * area, f"{vtp}: facets' area {area} != tributary areas"
    else:
        assert poly.GetNumberOfLines() == poly.GetNumberOfPoints() - 1, f"{vtp}: the interface is not a chain of lines"
    p, r, a = ip["p"], ip["r"], ip["tributary"]
    assert abs(p - r / a[:, None]).max() <= 1e-12 * max(1.0, abs(p).max()), f"{vtp}: p != r / a"
    lr, lg = (r ** 2).sum(axis=1) ** 0.5, (ip["r_xyz"] ** 2).sum(axis=1) ** 0.5
    assert abs(lr - lg).max() <= 1e-12 * max(1.0, lr.max()), f"{vtp}: |r_xyz| != |r|"
    path = os.path.join(run, f"interface_t{t:.12g}.csv")
    if os.path.exists(path):
        with open(path) as f:
            rows = list(csv.DictReader(f))
        assert len(rows) == poly.GetNumberOfPoints(), (len(rows), poly.GetNumberOfPoints())
        n, t = (2, "t1") if solid else (1, "t")  # local components: tangents first, the normal last
        for i, row in enumerate(rows):
            # The row's mesh node is the body's point at the row's coordinates, and the interface's point i.
            x = [float(row[c]) for c in ("x [mm]", "y [mm]", "z [mm]") if c in row]
            mesh_point, facet_point = grid.GetPoint(int(row["mesh node"])), poly.GetPoint(i)
            for k, xk in enumerate(x):
                assert abs(mesh_point[k] - xk) <= 1e-9 * max(1.0, abs(xk)), (vtu, i, "mesh node", mesh_point, x)
                assert abs(facet_point[k] - xk) <= 1e-9 * max(1.0, abs(xk)), (vtp, i, "point", facet_point, x)
            for mine, col in ((ip["beta"][i], "beta"), (ip["u"][i][n], "u_n [mm]"), (ip["u"][i][0], f"u_{t} [mm]"),
                              (ip["Rbar"][i][n], "Rbar_n [N]"), (ip["Rbar"][i][0], f"Rbar_{t} [N]")):
                assert abs(mine - float(row[col])) <= 1e-9 * max(1.0, abs(mine)), (vtp, i, col, mine, row[col])
        checked += 1
assert checked >= 1, "no frame at an output time"
print(f"{len(bodies)} passed, 0 failed")
