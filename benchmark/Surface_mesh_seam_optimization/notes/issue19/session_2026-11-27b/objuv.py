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
