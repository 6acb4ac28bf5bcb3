#!/usr/bin/python3
"""Opens the .pvd and every .vtu of a run with VTK's own XML reader and checks them against
the interface CSV: same beta at the contact nodes, mesh sizes as announced, no NaN.
Exit 77 (skipped) when python3-vtk9 is not installed."""
import csv
import math
import os
import sys
import xml.etree.ElementTree as ET

try:
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError:
    print("skipped: python3-vtk9 is not installed (tools/install-deps installs it)")
    sys.exit(77)

run = sys.argv[1]
datasets = [(float(d.get("timestep")), d.get("file")) for d in ET.parse(os.path.join(run, "results.pvd")).getroot().iter("DataSet")]
assert len(datasets) >= 1, "empty .pvd"
for t, name in datasets:
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(os.path.join(run, name))
    reader.Update()
    grid = reader.GetOutput()
    assert grid.GetNumberOfPoints() > 0 and grid.GetNumberOfCells() > 0, name
    pd, cd = grid.GetPointData(), grid.GetCellData()
    for arr in (pd.GetArray(i) for i in range(pd.GetNumberOfArrays())):
        assert not any(math.isnan(v) for v in vtk_to_numpy(arr).ravel()), f"NaN in {arr.GetName()}"
    assert cd.GetArray("von Mises [MPa]") is not None
    beta = vtk_to_numpy(pd.GetArray("beta"))
    contact = vtk_to_numpy(pd.GetArray("contact node"))
    with open(os.path.join(run, f"interface_t{t:g}.csv")) as f:
        rows = list(csv.DictReader(f))
    beta_vtk = [b for b, c in zip(beta, contact) if c > 0.5]
    assert len(beta_vtk) == len(rows), (len(beta_vtk), len(rows))
    for b, row in zip(beta_vtk, rows):
        assert abs(b - float(row["beta"])) <= 1e-9 * max(1.0, abs(b)), (b, row["beta"])
print(f"{len(datasets)} passed, 0 failed")
