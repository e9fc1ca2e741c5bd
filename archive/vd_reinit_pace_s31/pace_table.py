#!/usr/bin/python3
"""The blended neck with the reinitialisation per interface motion
(session 31, issue 27).

Reads the metrics.csv of `levelsinter` runs of
parameter_files/two_grains_blended_volume_diffusion_2d.prm given as
RULE:R_OVER_H=DIRECTORY (RULE `motion` at the study's step, `motion-half-dt`
at half of it), writes every step of every run to --csv (the columns of
vd_flux_blended_neck_2d.csv and the step's reinitialisation share
min(1, v dt / h_min), v = max_velocity), prints the markdown tables of x/R
at --times: the step's difference (half-dt against dt, relative to half-dt)
per mesh, and the difference per halving of h at the study's step
(relative to the finer mesh), and draws both to --png.
"""
import argparse
import csv
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "vd_smooth_neck_s30"))
from neck_table import R, T_STAR, finish, plot_difference  # noqa: E402



def read(directory):
    with open(directory + "/metrics.csv") as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows])
            for k in ("step", "time", "dt", "neck_radius", "volume_change",
                      "max_velocity")}


def at(m, times):
    return [np.interp(t, m["time"], m["neck_radius"] / R)
            if t <= m["time"][-1] * (1 + 1e-9) else None for t in times]


def percent(a, b):
    return "" if a is None or b is None else f"{100 * (b - a) / b:+.2f} %"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--csv")
    parser.add_argument("--png")
    parser.add_argument("--times", default="0.0003,0.0005,0.001,0.0015,"
                        "0.002,0.0025,0.003,0.0035,0.004,0.005")
    args = parser.parse_args()
    runs = {}
    for item in args.runs:
        rule, rest = item.split(":")
        r_over_h, directory = rest.split("=")
        runs[(rule, float(r_over_h))] = read(directory)
    if args.csv:
        with open(args.csv, "w") as out:
            out.write("rule,R_over_h,step,t,t_star,neck_over_R,"
                      "volume_change,max_velocity,reinitialisation_share\n")
            for (rule, r_over_h), m in sorted(runs.items()):
                h_min = R / r_over_h
                for i in range(len(m["step"])):
                    share = min(1., m["max_velocity"][i] * m["dt"][i] / h_min)
                    out.write(f"{rule},{r_over_h:g},{int(m['step'][i])},"
                              f"{m['time'][i]:.12g},"
                              f"{m['time'][i] * T_STAR:.10g},"
                              f"{m['neck_radius'][i] / R:.10g},"
                              f"{m['volume_change'][i]:.12g},"
                              f"{m['max_velocity'][i]:.8g},{share:.6g}\n")
    times = [float(t) for t in args.times.split(",")]
    print("| run | " + " | ".join(f"{1e3 * t:g} ms" for t in times) +
          " | steps, t reached |")
    print("|---" * (len(times) + 2) + "|")
    for (rule, r_over_h), m in sorted(runs.items(),
                                      key=lambda k: (k[0][1], k[0][0])):
        print(f"| {r_over_h:g}, {rule} | " + " | ".join(
            "-" if v is None else f"{v:.4f}" for v in at(m, times)) +
            f" | {len(m['step']) - 1}, {m['time'][-1]:.4g} s |")
    meshes = sorted({r for _, r in runs})
    for r_over_h in meshes:
        if ("motion", r_over_h) in runs and \
                ("motion-half-dt", r_over_h) in runs:
            a = at(runs[("motion", r_over_h)], times)
            b = at(runs[("motion-half-dt", r_over_h)], times)
            print(f"| {r_over_h:g}, dt / 2 - dt | " + " | ".join(
                percent(x, y) for x, y in zip(a, b)) + " | |")
    coarse_fine = [(c, f) for c, f in zip(meshes[:-1], meshes[1:])
                   if ("motion", c) in runs and ("motion", f) in runs]
    for c, f in coarse_fine:
        a = at(runs[("motion", c)], times)
        b = at(runs[("motion", f)], times)
        print(f"| {f:g} - {c:g} | " + " | ".join(
            percent(x, y) for x, y in zip(a, b)) + " | |")
    if args.png:
        fig, (top, bottom) = plt.subplots(2, 1, figsize=(6, 7), sharex=True)
        for (rule, r_over_h), m in sorted(runs.items()):
            top.plot(m["time"] * 1e3, m["neck_radius"] / R,
                     ls="--" if "half" in rule else "-",
                     label=f"R/h = {r_over_h:g}" +
                     (", dt / 2" if "half" in rule else ""))
        pairs = [(("motion", c), ("motion", f), f"{f:g} - {c:g}")
                 for c, f in coarse_fine]
        pairs += [(("motion", r), ("motion-half-dt", r),
                   f"{r:g}: dt / 2 - dt") for r in meshes
                  if ("motion", r) in runs and ("motion-half-dt", r) in runs]
        for coarse, fine, label in pairs:
            plot_difference(bottom, runs[coarse], runs[fine], label)
        finish(fig, top, bottom, "difference (%)",
               "Blended start, reinitialisation per interface motion",
               args.png)


if __name__ == "__main__":
    main()
