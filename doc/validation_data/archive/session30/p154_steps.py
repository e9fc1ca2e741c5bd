#!/usr/bin/env python3
"""The 154 coupled packing's time against the step: session 28's run of
the scene with the linear extension (../packing_154_s28/full154_progress.txt
and its resumed segment) and this session's with the limited one
(p154_lim_progress.txt). Prints a Markdown table. Run in this folder."""
import re


def times(*paths):
    t = {}
    for path in paths:
        for line in open(path):
            m = re.match(r"step\s+(\d+)\s+t =\s+(\S+)", line)
            if m:
                t[int(m.group(1))] = float(m.group(2))
    return t


linear = times("../packing_154_s28/full154_progress.txt",
               "../packing_154_s28/full154_resumed_np2_progress.txt")
limited = times("p154_lim_progress.txt")
print("| step | t, linear (s) | t, limited (s) | mean step since 0, linear "
      "| limited |")
print("|---|---|---|---|---|")
for step in sorted(set(linear) & set(limited)):
    if step == 0 or step % 2:
        continue
    print(f"| {step} | {linear[step]:.5f} | {limited[step]:.5f} | "
          f"{linear[step] / step:.2e} | {limited[step] / step:.2e} |")
