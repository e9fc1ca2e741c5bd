#!/usr/bin/python3
"""plot_field_check.py PLOT_FIELD STEM: scripts/plot_field.py reads the
fields of a 2-rank run as STEM.pvtu (the VTU file it names holds a piece
per rank) and as STEM.h5. Fails unless the VTU file has two pieces, the
two readings give the same nodes, quads and alpha (to float rounding), and
PNGs of alpha and of the velocity are written."""
import importlib.util
import pathlib
import subprocess
import sys

import numpy as np

script, stem = sys.argv[1], sys.argv[2]
spec = importlib.util.spec_from_file_location("plot_field", script)
plot_field = importlib.util.module_from_spec(spec)
spec.loader.exec_module(plot_field)

vtu = plot_field.read(stem + ".pvtu")
h5 = plot_field.read(stem + ".h5")
pieces = list(plot_field.vtu_pieces(stem + ".0.vtu"))
errors = []
if len(vtu[0]) != len(h5[0]) or len(vtu[1]) != len(h5[1]):
    errors.append(f"{len(vtu[0])} nodes and {len(vtu[1])} quads in the "
                  f"PVTU, {len(h5[0])} and {len(h5[1])} in the HDF5 file")
else:
    order_vtu = np.lexsort(vtu[0].T[::-1])
    order_h5 = np.lexsort(h5[0].T[::-1])
    node_error = np.abs(vtu[0][order_vtu] - h5[0][order_h5]).max()
    alpha_error = np.abs(vtu[2]["alpha"][order_vtu]
                         - h5[2]["alpha"][order_h5]).max()
    print(f"{len(vtu[0])} nodes, {len(vtu[1])} quads; largest difference "
          f"PVTU - HDF5: nodes {node_error:.2e}, alpha {alpha_error:.2e}")
    if node_error > 1e-6 or alpha_error > 1e-6:
        errors.append("the PVTU and the HDF5 file differ")
if len(pieces) != 2:
    errors.append(f"{stem}.0.vtu: {len(pieces)} pieces read, not 2")
for source, field in ((".pvtu", "alpha"), (".h5", "velocity")):
    png = pathlib.Path(pathlib.Path(stem).name + source + ".png")
    png.unlink(missing_ok=True)
    subprocess.run([script, stem + source, str(png), "--field", field],
                   check=True)
    if png.stat().st_size == 0:
        errors.append(f"{png} is empty")
for error in errors:
    print("FAIL:", error)
sys.exit(1 if errors else 0)
