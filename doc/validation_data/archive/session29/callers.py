import collections
import itertools
import sys
# callers.py FRAME STACKS [N]: of the samples of `perf script -F ip,sym
# --no-inline` (STACKS) that contain FRAME, the share each levelsinter
# frame above its outermost occurrence takes (the N largest).
frame, path = sys.argv[1], sys.argv[2]
lines = (line.strip() for line in open(path))
stacks = [[(line.split(None, 1) + ['?'])[1] for line in group]
          for nonempty, group in itertools.groupby(lines, key=bool) if nonempty]
hit = collections.Counter()
hits = 0
for stack in stacks:
    where = [i for i, f in enumerate(stack) if frame in f]
    if not where:
        continue
    hits += 1
    caller = next((f for f in stack[max(where) + 1:] if 'levelsinter' in f), '?')
    hit[caller[:110]] += 1
n = len(stacks)
print(f"{frame}: {100 * hits / n:.2f} % of {n}")
for name, count in hit.most_common(int(sys.argv[3]) if len(sys.argv) > 3 else 12):
    print(f"  {100 * count / n:6.2f} %  {name}")
