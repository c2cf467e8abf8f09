#!/usr/bin/env python3
"""Seam length inside a region of vertices, judged from the output OBJ alone.

  region_seams.py INPUT.obj OUTPUT_uv.obj SELECTED.txt [--json]

SELECTED.txt lists 0-based vertex indices of INPUT.obj (the OptCuts benchmark's
*_selected.txt). An edge is in the region when both its ends are selected. The
output's vertices are matched to the input's by position (exactly, then within
1e-9 of the bounding box diagonal). A seam is an edge with two faces whose UVs
differ at either end (beyond 1e-9 of the UV bounding box diagonal), as in
uvmetrics.py. Prints the seam length inside the region, the total seam length
(3D, and normalized by sqrt(area / pi)) and the region's share.
"""
import json
import math
import sys


def read_obj(path):
    V, T, F = [], [], []
    with open(path) as f:
        for line in f:
            p = line.split()
            if not p:
                continue
            if p[0] == 'v':
                V.append(tuple(float(x) for x in p[1:4]))
            elif p[0] == 'vt':
                T.append((float(p[1]), float(p[2])))
            elif p[0] == 'f':
                c = [q.split('/') for q in p[1:]]
                vi = [int(x[0]) - 1 if int(x[0]) > 0 else len(V) + int(x[0]) for x in c]
                ti = [int(x[1]) - 1 if len(x) > 1 and x[1] else -1 for x in c]
                for k in range(1, len(c) - 1):
                    F.append(((vi[0], vi[k], vi[k + 1]), (ti[0], ti[k], ti[k + 1])))
    return V, T, F


def main(argv):
    if len(argv) < 4:
        sys.exit(__doc__)
    Vin, _, _ = read_obj(argv[1])
    Vout, T, F = read_obj(argv[2])
    selected = set()
    with open(argv[3]) as f:
        for line in f:
            line = line.split('#')[0].strip()
            if line:
                selected.add(int(line.split()[0]))

    lo = [min(p[i] for p in Vin) for i in range(3)]
    hi = [max(p[i] for p in Vin) for i in range(3)]
    diag = math.dist(lo, hi)
    exact = {p: i for i, p in enumerate(Vin)}
    cell = max(diag * 1e-6, 1e-300)
    grid = {}
    for i, p in enumerate(Vin):
        grid.setdefault(tuple(int(math.floor(x / cell)) for x in p), []).append(i)

    def match(p):
        if p in exact:
            return exact[p]
        c = tuple(int(math.floor(x / cell)) for x in p)
        best, bd = -1, 1e-9 * diag
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    for i in grid.get((c[0] + dx, c[1] + dy, c[2] + dz), []):
                        d = math.dist(p, Vin[i])
                        if d <= bd:
                            best, bd = i, d
        if best < 0:
            sys.exit('output vertex %r matches no input vertex' % (p,))
        return best

    vin = [match(p) for p in Vout]
    ulo = [min(t[i] for t in T) for i in range(2)]
    uhi = [max(t[i] for t in T) for i in range(2)]
    uv_tol = 1e-9 * math.dist(ulo, uhi)

    # edge (a < b, input indices) -> list of (uv at a, uv at b)
    corners = {}
    area = 0.0
    for vs, ts in F:
        a3 = [Vout[v] for v in vs]
        e1 = [a3[1][i] - a3[0][i] for i in range(3)]
        e2 = [a3[2][i] - a3[0][i] for i in range(3)]
        cr = (e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0])
        area += 0.5 * math.sqrt(sum(x * x for x in cr))
        for k in range(3):
            a, b = vin[vs[k]], vin[vs[(k + 1) % 3]]
            ta, tb = T[ts[k]], T[ts[(k + 1) % 3]]
            if a > b:
                a, b, ta, tb = b, a, tb, ta
            corners.setdefault((a, b), []).append((ta, tb))
    total = inside = 0.0
    for (a, b), c in corners.items():
        if len(c) != 2:
            continue
        (p0, p1), (q0, q1) = c
        if math.dist(p0, q0) > uv_tol or math.dist(p1, q1) > uv_tol:
            length = math.dist(Vin[a], Vin[b])
            total += length
            if a in selected and b in selected:
                inside += length
    r = math.sqrt(area / math.pi)
    out = {'seam_length': total, 'seam_length_normalized': total / r,
           'region_seam_length': inside, 'region_seam_length_normalized': inside / r,
           'region_share': inside / total if total > 0 else 0.0,
           'selected_vertices': len(selected)}
    if '--json' in argv:
        print(json.dumps(out, indent=1))
    else:
        print('seams %.6g (normalized %.6g), inside the region %.6g (normalized %.6g, %.1f%%)' % (
            total, out['seam_length_normalized'], inside, out['region_seam_length_normalized'],
            100 * out['region_share']))


if __name__ == '__main__':
    main(sys.argv)
