import sys, numpy as np
sys.path.insert(0, '/work/conv/spike')
from vtu import read
for fn in sys.argv[1:]:
    d = read(fn)
    a = d['alpha']; sat = np.abs(a).max()
    near = np.abs(a) < 0.999 * sat
    v = np.linalg.norm(d['velocity'], axis=1)
    vv = np.linalg.norm(d['volume_diffusion_velocity'], axis=1)
    vs = np.abs(d['surface_diffusion_v_s'])
    i = np.argmax(np.where(near, v, 0))
    iv = np.argmax(np.where(near, vv, 0)); isd = np.argmax(np.where(near, vs, 0))
    print(fn.split('/')[-1], 'max|v| %.1f at %s alpha %.4f (vd %.1f, vs %.1f, kappa %.0f, xi %.3g, pid %d)' % (v[i], np.round(d['Points'][i],4), a[i], vv[i], vs[i], d['surface_diffusion_curvature'][i], d['volume_diffusion_xi'][i], d['particle_id'][i]),
          '| max vd %.1f at %s alpha %.4f | max vs %.1f at %s alpha %.4f' % (vv[iv], np.round(d['Points'][iv],4), a[iv], vs[isd], np.round(d['Points'][isd],4), a[isd]))
