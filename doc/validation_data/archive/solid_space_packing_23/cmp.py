import csv,sys
cols=["step","time","dt","volume_change","max_velocity","volume_diffusion_unsourced_cells","relative_density","neck_min","neck_mean","neck_max","centre_distance_change_mean"]
for f in sys.argv[1:]:
    rows=list(csv.DictReader(open(f+"/metrics.csv")))
    print("==",f, len(rows)-1,"steps")
    print(" ".join("%12s"%c[:12] for c in cols))
    for r in rows[::max(1,len(rows)//6)]+[rows[-1]]:
        print(" ".join("%12.5g"%float(r[c]) for c in cols))
