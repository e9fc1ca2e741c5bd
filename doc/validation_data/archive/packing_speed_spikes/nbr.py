import sys, numpy as np
sys.path.insert(0, '/work/conv/spike')
from vtu import read
p = np.array([float(x) for x in sys.argv[1].split(',')])
d = read(sys.argv[2])
P = d['Points']; a = d['alpha']
dist = np.linalg.norm(P - p, axis=1)
sel = np.where(dist < 0.025)[0]
# unique points
keys = {}
for i in sel:
    k = tuple(np.round(P[i], 4))
    keys.setdefault(k, i)
rows = sorted(keys.items(), key=lambda kv: kv[0])
for k, i in rows:
    vv = np.linalg.norm(d['volume_diffusion_velocity'][i])
    print('%s alpha %+.4f xi %+7.0f vd %5.1f p %+8.1f kappa %+6.0f pid %d' % (k, a[i], d['volume_diffusion_xi'][i], vv, d['volume_diffusion_pressure'][i], d['surface_diffusion_curvature'][i], d['particle_id'][i]))
