import sys, math
from collections import defaultdict
import os; sys.path.insert(0, os.path.dirname(os.path.abspath(__file__))); import objuv
V, F, FT, VT = objuv.read(sys.argv[1])
E=objuv.edge_uvs(F,FT,VT)
seam=[k for k,l in E.items() if len(l)==2 and l[0]!=l[1]]
bdv=set(v for k,l in E.items() if len(l)==1 for v in k)
adj=defaultdict(list)
for a,b in seam: adj[a].append(b); adj[b].append(a)
L=lambda a,b: math.dist(V[a],V[b])
nodes=[v for v in adj if len(adj[v])!=2 or v in bdv]
seen=set(); paths=[]
for n in nodes:
    for nb in adj[n]:
        e=(min(n,nb),max(n,nb))
        if e in seen: continue
        path=[n,nb]; seen.add(e)
        while path[-1] not in nodes:
            x=path[-1]; nxt=[y for y in adj[x] if (min(x,y),max(x,y)) not in seen]
            if not nxt: break
            y=nxt[0]; seen.add((min(x,y),max(x,y))); path.append(y)
        paths.append(path)
tot=sum(L(a,b) for a,b in seam)
print('seam length',round(tot,4),'edges',len(seam),'nodes',len(nodes))
for p in paths:
    l=sum(L(p[i],p[i+1]) for i in range(len(p)-1))
    kind=lambda v: 'B' if v in bdv else ('leaf' if len(adj[v])==1 else 'J%d'%len(adj[v]))
    print('  path %d-%d (%s..%s) edges %d len %.4f chord %.4f'%(p[0],p[-1],kind(p[0]),kind(p[-1]),len(p)-1,l,L(p[0],p[-1])))
