# render.py OBJ(with per-corner uv) PNG [view: x|y|z|-x..] : 3D view, seams red
import sys, zlib, struct, math
import os; sys.path.insert(0, os.path.dirname(os.path.abspath(__file__))); import objuv
V, F, FT, VT = objuv.read(sys.argv[1])
views=sys.argv[3].split(',') if len(sys.argv)>3 else ['z']
# seams: edge whose two sides have different uv pairs
E=objuv.edge_uvs(F,FT,VT)
seam=[k for k,l in E.items() if len(l)==2 and (l[0]!=l[1])]
bd=[k for k,l in E.items() if len(l)==1]
W=H=500
imgs=[]
for view in views:
    sign=-1 if view.startswith('-') else 1; ax='xyz'.index(view[-1])
    # camera looks along -sign*ax; screen axes the other two; elev tilt
    tilt=math.radians(30)
    def proj(p):
        o=[i for i in range(3) if i!=ax]
        u=p[o[0]]; w=p[o[1]]; d=sign*p[ax]
        # tilt around u axis
        w2=w*math.cos(tilt)+d*math.sin(tilt); d2=-w*math.sin(tilt)+d*math.cos(tilt)
        return (u,w2,d2)
    P=[proj(p) for p in V]
    us=[p[0] for p in P]; ws=[p[1] for p in P]
    s=min((W-20)/(max(us)-min(us)),(H-20)/(max(ws)-min(ws)))
    ox=(W-s*(max(us)+min(us)))/2; oy=(H+s*(max(ws)+min(ws)))/2
    S=[(ox+s*p[0], oy-s*p[1], p[2]) for p in P]
    zb=[[-1e30]*W for _ in range(H)]; img=[[(255,255,255)]*W for _ in range(H)]
    for f in F:
        a,b,c=(S[i] for i in f)
        pa,pb,pc=(V[i] for i in f)
        n=[(pb[1]-pa[1])*(pc[2]-pa[2])-(pb[2]-pa[2])*(pc[1]-pa[1]),(pb[2]-pa[2])*(pc[0]-pa[0])-(pb[0]-pa[0])*(pc[2]-pa[2]),(pb[0]-pa[0])*(pc[1]-pa[1])-(pb[1]-pa[1])*(pc[0]-pa[0])]
        nl=math.sqrt(sum(x*x for x in n)) or 1
        # light: screen-space normal approx via projected area sign
        area=(b[0]-a[0])*(c[1]-a[1])-(b[1]-a[1])*(c[0]-a[0])
        sh=int(80+150*min(1,abs(area)/(max(1e-12,nl*s*s))))
        x0=max(0,int(min(a[0],b[0],c[0]))); x1=min(W-1,int(max(a[0],b[0],c[0]))+1)
        y0=max(0,int(min(a[1],b[1],c[1]))); y1=min(H-1,int(max(a[1],b[1],c[1]))+1)
        if area==0: continue
        for y in range(y0,y1+1):
            for x in range(x0,x1+1):
                l1=((b[0]-x)*(c[1]-y)-(b[1]-y)*(c[0]-x))/area
                l2=((c[0]-x)*(a[1]-y)-(c[1]-y)*(a[0]-x))/area
                l3=1-l1-l2
                if l1<-1e-9 or l2<-1e-9 or l3<-1e-9: continue
                z=l1*a[2]+l2*b[2]+l3*c[2]
                if z>zb[y][x]: zb[y][x]=z; img[y][x]=(sh,sh,sh)
    def line(k,col):
        a,b=S[k[0]],S[k[1]]
        n=int(max(abs(b[0]-a[0]),abs(b[1]-a[1])))+1
        for i in range(n+1):
            t=i/n; x=int(a[0]+t*(b[0]-a[0])); y=int(a[1]+t*(b[1]-a[1])); z=a[2]+t*(b[2]-a[2])
            for dx in (0,1):
              for dy in (0,1):
                X,Y=x+dx,y+dy
                if 0<=X<W and 0<=Y<H and z>=zb[Y][X]-0.01*(max(ws)-min(ws)): img[Y][X]=col
    for k in bd: line(k,(0,0,255))
    for k in seam: line(k,(255,0,0))
    imgs.append(img)
# concat horizontally
rows=[]
for y in range(H):
    r=b'\x00'+b''.join(bytes(px) for img in imgs for px in img[y]); rows.append(r)
raw=b''.join(rows)
def chunk(t,d): return struct.pack('>I',len(d))+t+d+struct.pack('>I',zlib.crc32(t+d)&0xffffffff)
png=b'\x89PNG\r\n\x1a\n'+chunk(b'IHDR',struct.pack('>IIBBBBB',W*len(imgs),H,8,2,0,0,0))+chunk(b'IDAT',zlib.compress(raw,6))+chunk(b'IEND',b'')
open(sys.argv[2],'wb').write(png)
print('seam edges',len(seam),'boundary edges',len(bd))
