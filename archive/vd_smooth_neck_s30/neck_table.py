#!/usr/bin/python3
"""The blended start's neck at three meshes (session 30, issue 27).

Reads the metrics.csv of `levelsinter` runs of
parameter_files/two_grains_blended_volume_diffusion_2d.prm (one directory
per mesh, given as R_over_h=DIRECTORY), writes every step of every run to
--csv (rule, R_over_h, step, t, t_star, neck_over_R, volume_change, as
vd_flux_fillet_neck_2d.csv), prints the markdown table of x/R at --times
with the differences per halving (relative to the finer mesh), and draws
x/R against t and the differences to --png.
"""
import argparse
import csv

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

R = 0.2
T_STAR = 0.013 * 0.9 / R**3  # t* = C_v gamma t / R^3


def read(directory):
    with open(directory + "/metrics.csv") as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows])
            for k in ("step", "time", "neck_radius", "volume_change")}


def plot_difference(axis, coarse, fine, label):
    """Draw 100 (x_fine - x_coarse) / x_fine against t (ms) on axis."""
    t = fine["time"][fine["time"] <= coarse["time"][-1]]
    a = np.interp(t, coarse["time"], coarse["neck_radius"])
    b = np.interp(t, fine["time"], fine["neck_radius"])
    axis.plot(t * 1e3, 100 * (b - a) / b, label=label)


def finish(fig, top, bottom, difference_label, title, png):
    """Label the two panels (the 1 % aim dashed) and save to png."""
    top.set_ylabel("neck x / R")
    top.legend()
    bottom.axhline(1, color="grey", lw=0.5, ls="--")
    bottom.axhline(-1, color="grey", lw=0.5, ls="--")
    bottom.set_ylabel(difference_label)
    bottom.set_xlabel("t (ms)")
    bottom.legend()
    top.set_title(title)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--rule", default="blended")
    parser.add_argument("--csv")
    parser.add_argument("--png")
    parser.add_argument("--times", default="0.0003,0.0005,0.001,0.0015,"
                        "0.002,0.0025,0.003,0.0035,0.004,0.005")
    args = parser.parse_args()
    runs = []
    for item in args.runs:
        r_over_h, directory = item.split("=")
        runs.append((float(r_over_h), read(directory)))
    runs.sort(key=lambda r: r[0])
    if args.csv:
        with open(args.csv, "w") as out:
            out.write("rule,R_over_h,step,t,t_star,neck_over_R,"
                      "volume_change\n")
            for r_over_h, m in runs:
                for i in range(len(m["step"])):
                    out.write(f"{args.rule},{r_over_h:g},{int(m['step'][i])},"
                              f"{m['time'][i]:.12g},"
                              f"{m['time'][i] * T_STAR:.10g},"
                              f"{m['neck_radius'][i] / R:.10g},"
                              f"{m['volume_change'][i]:.12g}\n")
    times = [float(t) for t in args.times.split(",")]
    x = {}
    for r_over_h, m in runs:
        x[r_over_h] = [np.interp(t, m["time"], m["neck_radius"] / R)
                       if t <= m["time"][-1] * (1 + 1e-9) else None
                       for t in times]
        cells = f"{len(m['step']) - 1} steps to t = {m['time'][-1]:.4g} s"
        print(f"| {r_over_h:g} | " + " | ".join(
            "-" if v is None else f"{v:.4f}" for v in x[r_over_h]) +
            f" | {cells} |")
    for (c, _), (f, _) in zip(runs[:-1], runs[1:]):
        print(f"| difference {f:g} - {c:g} | " + " | ".join(
            "" if a is None or b is None else f"{100 * (b - a) / b:+.1f} %"
            for a, b in zip(x[c], x[f])) + " | |")
    if args.png:
        fig, (top, bottom) = plt.subplots(2, 1, figsize=(6, 7), sharex=True)
        for r_over_h, m in runs:
            top.plot(m["time"] * 1e3, m["neck_radius"] / R,
                     label=f"R/h = {r_over_h:g}")
        for (c, mc), (f, mf) in zip(runs[:-1], runs[1:]):
            plot_difference(bottom, mc, mf, f"{f:g} - {c:g}")
        finish(fig, top, bottom, "difference per halving (%)",
               "Two grains by volume diffusion, blended start", args.png)


if __name__ == "__main__":
    main()
