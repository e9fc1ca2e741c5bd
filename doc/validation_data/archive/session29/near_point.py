#!/usr/bin/python3
"""Interface nodes near a point in a levelsinter 3D VTU: their alpha, the
volume-diffusion velocity's normal component and xi, along a line.
usage: near_point.py FIELDS.vtu x y z radius"""
import sys
import numpy as np
sys.path.insert(0, '../packing_154_s28/unsourced_8')
from where_in_fields import read_hexes
pts, cells, f = read_hexes(sys.argv[1])
c = np.array([float(v) for v in sys.argv[2:5]]); r = float(sys.argv[5])
print(sorted(f.keys()))
d = np.linalg.norm(pts - c, axis=1)
sel = np.where(d < r)[0]
a = f['alpha'].ravel() if f['alpha'].ndim == 2 and f['alpha'].shape[1] == 1 else f['alpha']
seen = set()
rows = []
for i in sel:
    key = tuple(np.round(pts[i], 5))
    if key in seen: continue
    seen.add(key)
    vv = f['volume_diffusion_velocity'][i]
    xi = f['volume_diffusion_xi'][i] if 'volume_diffusion_xi' in f else [np.nan]
    rows.append((key, float(np.ravel(a[i])[0]), float(np.linalg.norm(vv)), float(np.ravel(xi)[0])))
rows.sort()
for k, al, v, xi in rows:
    if abs(al) < 0.03:
        print('%s alpha %+.4f |v_v| %7.3f xi %+9.2f' % (k, al, v, xi))
