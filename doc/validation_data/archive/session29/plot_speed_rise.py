#!/usr/bin/python3
"""packing_speed_rise_8.png: largest interface speed, step and mean neck
against t for the 8-sphere runs of doc/validation.md, "Packings: the late
rise of the largest speed" (their metrics.csv files in this folder).
Run from this folder: /usr/bin/python3 plot_speed_rise.py"""
import csv

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

RUNS = [('speed_rise_8_cfl15', 'scene (CFL 1.5, linear extrapolation)'),
        ('speed_rise_8_cfl05', 'CFL 0.5'),
        ('speed_rise_8_joined_cfl15', 'near-misses joined at t = 0'),
        ('speed_rise_8_exp_const', 'Extrapolation = constant')]
fig, ax = plt.subplots(1, 3, figsize=(14, 4))
for (name, label), colour in zip(RUNS, ['C0', 'C1', 'C2', 'C3']):
    rows = list(csv.DictReader(open(name + '_metrics.csv')))[1:]
    t = [float(r['time']) for r in rows]
    for axis, column in zip(ax, ['max_velocity', 'dt', 'neck_mean']):
        if column == 'neck_mean' and 'joined' in name:
            continue  # other solid: its necks are not comparable
        axis.plot(t, [float(r[column]) for r in rows], 'o-', ms=3,
                  label=label, color=colour)
for axis, what in zip(ax, ['largest interface speed (um/s)', 'dt (s)',
                           'mean neck radius (um, joined run omitted)']):
    axis.set_xlabel('t (s)')
    axis.set_ylabel(what)
ax[0].legend(fontsize=8)
fig.suptitle('8 spheres like the 154, coupled scene, 1 rank')
fig.tight_layout()
fig.savefig('packing_speed_rise_8.png', dpi=80)
