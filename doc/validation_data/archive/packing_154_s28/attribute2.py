import sys, collections
# Within samples containing FRAME (innermost occurrence), the frame just below it.
frame = sys.argv[1]
stacks, cur = [], []
for line in open('full154_stacks.txt'):
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
    i = min(idx)
    hit[(st[i-1] if i > 0 else '(self)')[:120]] += 1
print(f"{frame}: {100*tot/n:.2f} %")
for k, v in hit.most_common(15): print(f"  {100*v/n:6.2f} %  {k}")
