import csv, sys
skip = {'wall_time','transport_iterations','surface_diffusion_iterations','surface_diffusion_solve_cpu_time','volume_diffusion_mechanics_iterations','volume_diffusion_xi_iterations'}
a = list(csv.DictReader(open(sys.argv[1])))
for f in sys.argv[2:]:
    b = list(csv.DictReader(open(f)))
    per = {}
    for ra, rb in zip(a, b):
        for k in ra:
            if k in skip: continue
            x, y = float(ra[k]), float(rb[k])
            d = abs(x - y) / max(abs(x), abs(y), 1e-12)
            per[k] = max(per.get(k, 0), d)
    top = sorted(per.items(), key=lambda kv: -kv[1])[:7]
    print(f, ', '.join('%s %.1e' % kv for kv in top))
