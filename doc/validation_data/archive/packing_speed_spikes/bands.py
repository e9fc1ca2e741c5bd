import sys, numpy as np
sys.path.insert(0, '/work/conv/spike')
from vtu import read
h = 0.009375
for fn in sys.argv[1:]:
    d = read(fn)
    a = d['alpha']; sat = np.abs(a).max()
    v = np.linalg.norm(d['velocity'], axis=1)
    row = []
    for w in [0.5, 1, 2, 3, 99]:
        sel = (np.abs(a) < w*h) & (np.abs(a) < 0.999*sat)
        row.append('%.1f' % v[sel].max())
    # cells that contain the interface: nodes of cells with sign change
    n = 8
    ac = a.reshape(-1, n)
    cut = (ac.min(1) < 0) & (ac.max(1) > 0)
    vc = v.reshape(-1, n)[cut]
    print(fn.split('/')[-1], 'max|v| for |alpha|<0.5h,1h,2h,3h,ramp:', row, 'cut cells: %.1f (99.9%%: %.1f, 99%%: %.1f)' % (vc.max(), np.percentile(vc, 99.9), np.percentile(vc, 99)))
