import sys, numpy as np
sys.path.insert(0, '/work/conv/spike')
from vtu import read
d = read(sys.argv[1]); field = sys.argv[2]; z0 = float(sys.argv[3])
x0,x1,y0,y1 = [float(v) for v in sys.argv[4].split(',')]
P = d['Points']; f = d[field] if d[field].ndim == 1 else np.linalg.norm(d[field], axis=1)
sel = (np.abs(P[:,2]-z0) < 1e-3) & (P[:,0] >= x0) & (P[:,0] <= x1) & (P[:,1] >= y0) & (P[:,1] <= y1)
pts = {}
for i in np.where(sel)[0]:
    pts[(round(P[i,0],4), round(P[i,1],4))] = f[i]
xs = sorted(set(k[0] for k in pts)); ys = sorted(set(k[1] for k in pts), reverse=True)
print('y\\x   ' + ' '.join('%7.4f' % x for x in xs))
for y in ys:
    print('%.4f ' % y + ' '.join(('%7.1f' % pts[(x,y)]) if (x,y) in pts else '      .' for x in xs))
