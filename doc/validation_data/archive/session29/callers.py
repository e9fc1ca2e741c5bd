import sys, collections
# Samples containing FRAME: the caller frame just above its outermost occurrence.
frame, path = sys.argv[1], sys.argv[2]
stacks, cur = [], []
for line in open(path):
    s = line.strip()
    if not s:
        if cur: stacks.append(cur); cur = []
        continue
    parts = s.split(None, 1)
    cur.append(parts[1] if len(parts) > 1 else '?')
if cur: stacks.append(cur)
n = len(stacks)
hit = collections.Counter(); tot = 0
for st in stacks:
    idx = [i for i, f in enumerate(st) if frame in f]
    if not idx: continue
    tot += 1
    i = max(idx)
    # the first levelsinter frame above it
    j = i + 1
    while j < len(st) and 'levelsinter' not in st[j]: j += 1
    hit[(st[j] if j < len(st) else '?')[:110]] += 1
print(f"{frame}: {100*tot/n:.2f} % of {n}")
for k, v in hit.most_common(int(sys.argv[3]) if len(sys.argv) > 3 else 12): print(f"  {100*v/n:6.2f} %  {k}")
