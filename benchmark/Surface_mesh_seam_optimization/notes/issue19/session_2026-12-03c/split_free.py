# Free (overlapping) result split into overlap-free pieces by greedy BFS; each
# corner keeps its UV (E_SD unchanged); pieces shifted apart. Estimate only.
import sys, math, collections
sys.path.insert(0, '/work/shared/tools')
import uvmetrics
src, dst = sys.argv[1], sys.argv[2]
V, VT, F = [], [], []
for l in open(src):
    t = l.split()
    if not t: continue
    if t[0] == 'v': V.append(l)
    elif t[0] == 'vt': VT.append(tuple(map(float, t[1:3])))
    elif t[0] == 'f': F.append([(int(a.split('/')[0]) - 1, int(a.split('/')[1]) - 1) for a in t[1:]])
n = len(F)
tris = []
for f in F:
    (x0, y0), (x1, y1), (x2, y2) = [VT[c[1]] for c in f]
    d = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
    tris.append((x0, y0, x1, y1, x2, y2, 1.0 if d > 0 else -1.0))
xs = [p[0] for p in VT]; ys = [p[1] for p in VT]
diag = math.hypot(max(xs) - min(xs), max(ys) - min(ys))
pairs, _, _ = uvmetrics.find_overlaps(tris, 1e-9 * diag, 10**9)
ov = collections.defaultdict(set)
for i, j in pairs: ov[i].add(j); ov[j].add(i)
# UV adjacency: faces sharing an edge with the same two vt
edge = collections.defaultdict(list)
for fi, f in enumerate(F):
    for k in range(3):
        a, b = f[k][1], f[(k + 1) % 3][1]
        edge[(min(a, b), max(a, b))].append(fi)
adj = collections.defaultdict(list)
for fs in edge.values():
    if len(fs) == 2: adj[fs[0]].append(fs[1]); adj[fs[1]].append(fs[0])
piece = [-1] * n
np_ = 0
for s in range(n):
    if piece[s] >= 0: continue
    members = set([s]); piece[s] = np_
    q = collections.deque([s])
    while q:
        f = q.popleft()
        for g in adj[f]:
            if piece[g] < 0 and not (ov[g] & members):
                piece[g] = np_; members.add(g); q.append(g)
    np_ += 1
out = open(dst, 'w')
for l in V: out.write(l)
vt_id = {}
w = max(xs) - min(xs) + 1
lines = []
for fi, f in enumerate(F):
    ids = []
    for (v, t) in f:
        key = (piece[fi], t)
        if key not in vt_id:
            vt_id[key] = len(vt_id)
            u, vv = VT[t]
            out.write('vt %.17g %.17g\n' % (u + 1.5 * w * piece[fi], vv))
        ids.append('%d/%d' % (v + 1, vt_id[key] + 1))
    lines.append('f ' + ' '.join(ids) + '\n')
out.writelines(lines)
print('pairs', len(pairs), 'pieces', np_)
