# objuv.read(path) -> V (3D points), F (vertex indices), FT (vt indices, -1 if none), VT (UVs): triangles of an OBJ
def read(path):
    V = []; F = []; FT = []; VT = []
    for l in open(path):
        s = l.split()
        if not s: continue
        if s[0] == 'v': V.append(tuple(map(float, s[1:4])))
        elif s[0] == 'vt': VT.append(tuple(map(float, s[1:3])))
        elif s[0] == 'f':
            F.append([int(t.split('/')[0]) - 1 for t in s[1:]])
            FT.append([int(t.split('/')[1]) - 1 if '/' in t and t.split('/')[1] else -1 for t in s[1:]])
    return V, F, FT, VT


# edge_uvs(F, FT, VT) -> {(a, b) with a < b: [(uv at a, uv at b) for each face on the edge]}:
# a seam is an edge with two different entries, a border edge has one
def edge_uvs(F, FT, VT):
    E = {}
    for fi, f in enumerate(F):
        for i in range(3):
            a, b = f[i], f[(i + 1) % 3]; ta, tb = FT[fi][i], FT[fi][(i + 1) % 3]
            E.setdefault((min(a, b), max(a, b)), []).append((VT[ta], VT[tb]) if a < b else (VT[tb], VT[ta]))
    return E
