# cut.py MESH.obj OUT.obj theta1[,theta2,...] : radial seams border -> tube top -> inner contact at each angle (degrees);
# writes OUT.obj with per-corner vt indices of the cut (UVs zero: run tutte.py after)
import sys, math, heapq
from collections import defaultdict
V=[];F=[]
for l in open(sys.argv[1]):
    p=l.split()
    if not p: continue
    if p[0]=='v': V.append(tuple(map(float,p[1:4])))
    elif p[0]=='f': F.append([int(x.split('/')[0])-1 for x in p[1:]])
adj=defaultdict(set); ecount=defaultdict(int)
for f in F:
    for i in range(3):
        a,b=f[i],f[(i+1)%3]; adj[a].add(b); adj[b].add(a); ecount[(min(a,b),max(a,b))]+=1
border=set(v for e,c in ecount.items() if c==1 for v in e)
def nearest(p, cand=None):
    c=cand if cand is not None else range(len(V))
    return min(c, key=lambda i: math.dist(V[i],p))
def dijkstra(s,t):
    d={s:0.0}; prev={}; h=[(0.0,s)]
    while h:
        dd,v=heapq.heappop(h)
        if v==t: break
        if dd>d[v]: continue
        for w in adj[v]:
            nd=dd+math.dist(V[v],V[w])
            if nd<d.get(w,1e300): d[w]=nd; prev[w]=v; heapq.heappush(h,(nd,w))
    path=[t]
    while path[-1]!=s: path.append(prev[path[-1]])
    return path[::-1], d[t]
R=40.69; zt=23.89; zb=-22.08
cut=set(); total=0
for th in map(float, sys.argv[3].split(',')):
    c,s=math.cos(math.radians(th)), math.sin(math.radians(th))
    b=max(border, key=lambda i: V[i][0]*c+V[i][1]*s - 1e-3*abs(-V[i][0]*s+V[i][1]*c))
    t=nearest((R*c,R*s,zt)); inn=nearest((31.5*c,31.5*s,zb))
    p1,l1=dijkstra(b,t); p2,l2=dijkstra(t,inn)
    path=p1+p2[1:]; total+=l1+l2
    print('theta',th,'border',b,V[b],'top',t,'inner',inn,V[inn],'length',l1+l2, file=sys.stderr)
    for i in range(len(path)-1): cut.add((min(path[i],path[i+1]),max(path[i],path[i+1])))
print('seam length',total,'normalized',total/132.6833606333408, file=sys.stderr)
# corners: union over non-cut interior edges
par={}
def fd(x):
    while par.setdefault(x,x)!=x: par[x]=par[par[x]]; x=par[x]
    return x
dface={}
for fi,f in enumerate(F):
    for i in range(3): dface[(f[i],f[(i+1)%3])]=fi
for fi,f in enumerate(F):
    for i in range(3):
        v=f[i]; w=f[(i+1)%3]
        if (min(v,w),max(v,w)) in cut: continue
        g=dface.get((w,v))
        if g is None: continue
        # corner of v in g and corner of w in g
        gv=F[g].index(v); gw=F[g].index(w)
        par[fd((fi,i))]=fd((g,gv)); par[fd((fi,(i+1)%3))]=fd((g,gw))
ids={}; FT=[]
for fi,f in enumerate(F):
    row=[]
    for i in range(3):
        r=fd((fi,i)); ids.setdefault(r,len(ids)); row.append(ids[r])
    FT.append(row)
with open(sys.argv[2],'w') as o:
    for p in V: o.write('v %.17g %.17g %.17g\n'%p)
    for k in range(len(ids)): o.write('vt 0 0\n')
    for f,ft in zip(F,FT): o.write('f '+' '.join('%d/%d'%(a+1,b+1) for a,b in zip(f,ft))+'\n')
print('uv vertices',len(ids),'vertices',len(V), file=sys.stderr)
