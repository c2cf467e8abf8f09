# tutte.py IN.obj OUT.obj : keep IN's seams (per-corner vt), replace UVs by a Tutte map (uniform weights, border on a circle by arc length)
import sys, math
import os; sys.path.insert(0, os.path.dirname(os.path.abspath(__file__))); import objuv
V, F, FT, VT = objuv.read(sys.argv[1])
from collections import defaultdict
def uv_to_vertex(F, FT):
    return {t: v for f, ft in zip(F, FT) for v, t in zip(f, ft)}
def loops_of(FT):
    cnt=defaultdict(int)
    for ft in FT:
        for i in range(3): cnt[(ft[i],ft[(i+1)%3])]+=1
    bn={a:b for (a,b) in cnt if (b,a) not in cnt}
    seen=set(); lps=[]
    for a in bn:
        if a in seen: continue
        lp=[a]; seen.add(a); x=bn[a]
        while x!=a: lp.append(x); seen.add(x); x=bn[x]
        lps.append(lp)
    return lps
import heapq
while True:
    lps=loops_of(FT)
    if len(lps)<=1: break
    p3=uv_to_vertex(F,FT)
    adj=defaultdict(set)
    for ft in FT:
        for i in range(3): a,b=ft[i],ft[(i+1)%3]; adj[a].add(b); adj[b].add(a)
    bset=set(v for lp in lps for v in lp)
    lps.sort(key=len, reverse=True)
    src=set(lps[0]); target_of={v:k for k,lp in enumerate(lps) if k>0 for v in lp}
    dist={v:0.0 for v in src}; prev={}; h=[(0.0,v) for v in src]; heapq.heapify(h); hit=None
    while h:
        d,v=heapq.heappop(h)
        if d>dist.get(v,1e300): continue
        if v in target_of: hit=v; break
        for w in adj[v]:
            if v in src and w in src: continue
            if w in bset and w not in target_of: continue
            nd=d+math.dist(V[p3[v]],V[p3[w]])
            if nd<dist.get(w,1e300): dist[w]=nd; prev[w]=v; heapq.heappush(h,(nd,w))
    path=[hit]
    while path[-1] not in src: path.append(prev[path[-1]])
    cut=set((min(path[i],path[i+1]),max(path[i],path[i+1])) for i in range(len(path)-1))
    # relabel corners
    par={}
    def fd(x):
        while par.setdefault(x,x)!=x: par[x]=par[par[x]]; x=par[x]
        return x
    dface={}
    for fi,ft in enumerate(FT):
        for i in range(3): dface[(ft[i],ft[(i+1)%3])]=fi
    for fi,ft in enumerate(FT):
        for i in range(3):
            v=ft[i]; w=ft[(i+1)%3]
            if (min(v,w),max(v,w)) in cut: continue
            g=dface.get((w,v))
            if g is None: continue
            fd((fi,i)); gi=FT[g].index(v); par[fd((fi,i))]=fd((g,gi))
    newid={}; nVT=[]
    NFT=[]
    for fi,ft in enumerate(FT):
        row=[]
        for i in range(3):
            r=fd((fi,i))
            if r not in newid: newid[r]=len(nVT); nVT.append(VT[ft[i]])
            row.append(newid[r])
        NFT.append(row)
    FT=NFT; VT=nVT
    print('connected a hole by a path of',len(path)-1,'edges; uv vertices',len(VT))
n=len(VT)
pos3=uv_to_vertex(F,FT)
nb=defaultdict(set)
for ft in FT:
    for i in range(3):
        a,b=ft[i],ft[(i+1)%3]; nb[a].add(b); nb[b].add(a)
loops=loops_of(FT)
print("loops",[len(l) for l in loops]); loops.sort(key=len, reverse=True)
loop=loops[0]
L=[math.dist(V[pos3[loop[i]]],V[pos3[loop[(i+1)%len(loop)]]]) for i in range(len(loop))]
tot=sum(L); R=tot/(2*math.pi)
uv=[[0.0,0.0] for _ in range(n)]; fixed=[False]*n; acc=0
for i,a in enumerate(loop):
    th=2*math.pi*acc/tot; uv[a]=[R*math.cos(th),R*math.sin(th)]; fixed[a]=True; acc+=L[i]
free=[i for i in range(n) if not fixed[i]]
# CG on Laplacian (uniform): deg*x_i - sum x_j = sum fixed
idx={v:k for k,v in enumerate(free)}
for d in (0,1):
    b=[sum(uv[j][d] for j in nb[v] if fixed[j]) for v in free]
    x=[0.0]*len(free)
    def A(x): return [len(nb[v])*x[k]-sum(x[idx[j]] for j in nb[v] if not fixed[j]) for k,v in enumerate(free)]
    r=[bi-ai for bi,ai in zip(b,A(x))]; p=r[:]; rr=sum(t*t for t in r)
    for it in range(5000):
        Ap=A(p); a=rr/sum(pi*api for pi,api in zip(p,Ap))
        x=[xi+a*pi for xi,pi in zip(x,p)]; r=[ri-a*api for ri,api in zip(r,Ap)]
        rr2=sum(t*t for t in r)
        if rr2<1e-24*max(1,sum(t*t for t in b)): break
        p=[ri+rr2/rr*pi for ri,pi in zip(r,p)]; rr=rr2
    for k,v in enumerate(free): uv[v][d]=x[k]
with open(sys.argv[2],'w') as o:
    for p in V: o.write('v %.17g %.17g %.17g\n'%p)
    for t in uv: o.write('vt %.17g %.17g\n'%tuple(t))
    for f,ft in zip(F,FT): o.write('f '+' '.join('%d/%d'%(a+1,b+1) for a,b in zip(f,ft))+'\n')
print('tutte: uv vertices',n,'border',len(loop))
