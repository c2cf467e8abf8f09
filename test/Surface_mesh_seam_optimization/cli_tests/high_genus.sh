#!/bin/bash
# A torus is cut through its handle (a meridian and a parallel through one
# vertex) and then optimized as any disk: both modes succeed, and the written
# OBJ has one chart, no flipped triangle and the seams the report gives.
set -u
BIN=$1 DATA=$2 SCRATCH=$3
mkdir -p "$SCRATCH" && cd "$SCRATCH" || exit 1
rm -f ./*
fail() { echo "FAIL: $*" >&2; exit 1; }

python3 - >torus.obj <<'PY'
import math
n, m = 12, 6  # around the hole, around the tube
for i in range(n):
    for j in range(m):
        a, b = 2 * math.pi * i / n, 2 * math.pi * j / m
        r = 1 + 0.4 * math.cos(b)
        print("v %.17g %.17g %.17g" % (r * math.cos(a), r * math.sin(a), 0.4 * math.sin(b)))
idx = lambda i, j: (i % n) * m + (j % m) + 1
for i in range(n):
    for j in range(m):
        print("f %d %d %d" % (idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)))
        print("f %d %d %d" % (idx(i, j), idx(i + 1, j + 1), idx(i, j + 1)))
PY

# checks an OBJ with per-corner UVs: one chart, no flip, the seam length of the report
check() {
  python3 - "$1" "$2" <<'PY' || fail "$1: $(cat check.txt 2>/dev/null)"
import json, math, sys
obj, report = sys.argv[1], json.load(open(sys.argv[2]))
V, T, F = [], [], []
for line in open(obj):
    p = line.split()
    if not p: continue
    if p[0] == 'v': V.append(tuple(map(float, p[1:4])))
    elif p[0] == 'vt': T.append(tuple(map(float, p[1:3])))
    elif p[0] == 'f': F.append([tuple(int(x) - 1 for x in c.split('/')[:2]) for c in p[1:]])
flips = 0
for f in F:
    (a, ta), (b, tb), (c, tc) = f
    ua, ub, uc = T[ta], T[tb], T[tc]
    if (ub[0] - ua[0]) * (uc[1] - ua[1]) - (ub[1] - ua[1]) * (uc[0] - ua[0]) <= 0: flips += 1
# sides: (v0, v1) -> (t0, t1); an edge is a seam if its two sides' UVs differ
side = {}
for f in F:
    for k in range(3):
        (v0, t0), (v1, t1) = f[k], f[(k + 1) % 3]
        side[(v0, v1)] = (T[t0], T[t1])
seam = 0.0
for (v0, v1), (u0, u1) in side.items():
    if v0 < v1 and (v1, v0) in side:
        w1, w0 = side[(v1, v0)]
        if u0 != w0 or u1 != w1: seam += math.dist(V[v0], V[v1])
# charts: faces joined across non-seam edges
parent = list(range(len(F)))
def find(i):
    while parent[i] != i: parent[i] = parent[parent[i]]; i = parent[i]
    return i
where = {}
for i, f in enumerate(F):
    for k in range(3):
        where[(f[k][0], f[(k + 1) % 3][0])] = i
for (v0, v1), i in where.items():
    j = where.get((v1, v0))
    if j is not None and side[(v0, v1)] == tuple(reversed(side[(v1, v0)])): parent[find(i)] = find(j)
charts = len({find(i) for i in range(len(F))})
msg = "flips %d charts %d seam %.9g report %.9g" % (flips, charts, seam, report["seam_length"])
open("check.txt", "w").write(msg)
sys.exit(0 if flips == 0 and charts == 1 and seam > 0 and abs(seam - report["seam_length"]) <= 1e-6 * seam else 1)
PY
}

"$BIN" torus.obj --keep-seams -o keep.obj --report keep.json >out.txt 2>err.txt
rc=$?
[ "$rc" -eq 0 ] || fail "--keep-seams: exit code $rc (stderr: $(cat err.txt))"
python3 -c 'import json,sys; r=json.load(open("keep.json")); sys.exit(r["status"] != "OK" or r["charts"] != 1)' \
  || fail "--keep-seams report: $(cat keep.json)"
check keep.obj keep.json

"$BIN" torus.obj -o opt.obj --report opt.json >out.txt 2>err.txt
rc=$?
[ "$rc" -eq 0 ] || fail "default mode: exit code $rc (stderr: $(cat err.txt))"
python3 -c 'import json,sys; r=json.load(open("opt.json")); sys.exit(r["status"] != "OK" or not r["bound_met"] or r["e_sd"] > 4.1 or r["overlapping_triangle_pairs"] != 0)' \
  || fail "default mode report: $(cat opt.json)"
check opt.obj opt.json
echo "ok"
