#!/usr/bin/python3
"""The xi ridge along the grid line y = Y through the point (x, z): for
each step's VTU, alpha and xi at y = Y and at the grid lines y = Y -+ h,
at the node of the row nearest the interface. usage: ridge.py x Y z h VTU..."""
import sys
import numpy as np
sys.path.insert(0, '../packing_154_s28/unsourced_8')
from where_in_fields import read_hexes
x, Y, z, h = map(float, sys.argv[1:5])
for path in sys.argv[5:]:
    pts, cells, f = read_hexes(path)
    a = f['alpha'].ravel(); xi = f['volume_diffusion_xi'].ravel()
    out = []
    for y in (Y - h, Y, Y + h):
        m = (np.abs(pts[:, 0] - x) < 1e-4) & (np.abs(pts[:, 1] - y) < 1e-4) & (np.abs(pts[:, 2] - z) < 0.03)
        idx = np.where(m)[0]
        if len(idx) == 0:
            out.append('(none)'); continue
        k = idx[np.argmin(np.abs(a[idx]))]
        out.append('z %.4f alpha %+.4f xi %+7.1f' % (pts[k, 2], a[k], xi[k]))
    print(path.split('/')[-1], ' | '.join(out))
