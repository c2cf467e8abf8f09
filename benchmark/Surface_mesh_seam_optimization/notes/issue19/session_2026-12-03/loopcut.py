# loopcut.py IN.obj OUT.obj : cut the shortest path (3D) between the first two boundary loops; per-corner vt (zero UVs)
import sys, math, heapq
from collections import defaultdict
V=[];F=[]
for l in open(sys.argv[1]):
    p=l.split()
    if not p: continue
    if p[0]=='v': V.append(tuple(map(float,p[1:4])))
    elif p[0]=='f': F.append([int(x.split('/')[0])-1 for x in p[1:]])
ecount=defaultdict(int); adj=defaultdict(set)
for f in F:
    for i in range(3):
        a,b=f[i],f[(i+1)%3]; ecount[(min(a,b),max(a,b))]+=1; adj[a].add(b); adj[b].add(a)
bedges=[e for e,c in ecount.items() if c==1]
# loops by union-find over boundary edges
par={}
def find(x):
    while par.setdefault(x,x)!=x: par[x]=par[par[x]]; x=par[x]
    return x
for a,b in bedges: par[find(a)]=find(b)
loops=defaultdict(set)
for a,b in bedges: loops[find(a)].update((a,b))
L=sorted(loops.values(), key=len, reverse=True)
print('loops', [len(x) for x in L], file=sys.stderr)
A,B=L[0],L[1]
bverts=set().union(*L)
d={v:0. for v in A}; prev={}
pq=[(0.,v) for v in A]; heapq.heapify(pq); end=None
while pq:
    dv,v=heapq.heappop(pq)
    if dv>d.get(v,1e300): continue
    if v in B: end=v; break
    for w in adj[v]:
        if w in A: continue
        if w in bverts and w not in B: continue
        # no boundary edges along the path
        if ecount[(min(v,w),max(v,w))]==1: continue
        nd=dv+math.dist(V[v],V[w])
        if nd<d.get(w,1e300): d[w]=nd; prev[w]=v; heapq.heappush(pq,(nd,w))
path=[end]
while path[-1] in prev: path.append(prev[path[-1]])
print('path edges', len(path)-1, 'length', d[end], file=sys.stderr)
seam=set((min(a,b),max(a,b)) for a,b in zip(path,path[1:]))
# per vertex, group incident faces: faces adjacent across a non-seam interior edge incident to v share a vt
vf=defaultdict(list)
for fi,f in enumerate(F):
    for v in f: vf[v].append(fi)
vt={}  # (face, vertex) -> vt index
nvt=0
for v,fs in vf.items():
    p2={fi:fi for fi in fs}
    def fd(x):
        while p2[x]!=x: p2[x]=p2[p2[x]]; x=p2[x]
        return x
    byedge=defaultdict(list)
    for fi in fs:
        for w in F[fi]:
            if w!=v: byedge[(min(v,w),max(v,w))].append(fi)
    for e,l in byedge.items():
        if len(l)==2 and e not in seam: p2[fd(l[0])]=fd(l[1])
    ids={}
    for fi in fs:
        r=fd(fi)
        if r not in ids: ids[r]=nvt; nvt+=1
        vt[(fi,v)]=ids[r]
with open(sys.argv[2],'w') as o:
    for v in V: o.write('v %.17g %.17g %.17g\n'%v)
    for k in range(nvt): o.write('vt 0 0\n')
    for fi,f in enumerate(F): o.write('f '+' '.join('%d/%d'%(v+1,vt[(fi,v)]+1) for v in f)+'\n')
