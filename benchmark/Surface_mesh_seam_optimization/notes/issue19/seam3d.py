# Renders a mesh with per-corner UVs (OBJ) from three directions, its seams
# (edges whose two sides' UVs differ, and borders) in red: seam3d.py in.obj out.png
import os, sys, math
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from uvpng import load, png
def render(obj,out,views=((0,0),(90,0),(0,90)),W=400):
    V,T,F=load(obj)
    # seam edges: mesh edges whose two corners' uv differ, or border
    E={}
    for fv,ft in F:
        for k in range(3):
            a,b=fv[k],fv[(k+1)%3]
            E.setdefault((min(a,b),max(a,b)),[]).append({a:T[ft[k]],b:T[ft[(k+1)%3]]})
    seams=[e for e,l in E.items() if len(l)==1 or l[0]!=l[1]]
    panels=[]
    cx=[sum(v[i] for v in V)/len(V) for i in range(3)]
    R=max(math.dist(v,cx) for v in V)
    for yaw,pitch in views:
        cy,sy=math.cos(math.radians(yaw)),math.sin(math.radians(yaw))
        cp,sp=math.cos(math.radians(pitch)),math.sin(math.radians(pitch))
        def tr(v):
            x,y,z=v[0]-cx[0],v[1]-cx[1],v[2]-cx[2]
            x,z=cy*x+sy*z,-sy*x+cy*z
            y,z=cp*y-sp*z,sp*y+cp*z
            return ((x/R*0.95+1)*W/2,(1-y/R*0.95)*W/2,z)
        P=[tr(v) for v in V]
        px=bytearray([255]*(W*W*3)); zb=[-1e9]*(W*W)
        for fv,ft in F:
            a,b,c=[P[i] for i in fv]
            d=(b[0]-a[0])*(c[1]-a[1])-(b[1]-a[1])*(c[0]-a[0])
            if d==0: continue
            n=abs(d)/(math.hypot(*(b[0]-a[0],b[1]-a[1]))*math.hypot(*(c[0]-a[0],c[1]-a[1]))+1e-12)
            # shade by 3D normal z component
            A=[V[i] for i in fv]
            u=[A[1][i]-A[0][i] for i in range(3)]; w=[A[2][i]-A[0][i] for i in range(3)]
            nn=[u[1]*w[2]-u[2]*w[1],u[2]*w[0]-u[0]*w[2],u[0]*w[1]-u[1]*w[0]]
            pa,pb,pc=a,b,c
            nz=abs((pb[0]-pa[0])*(pc[1]-pa[1])-(pb[1]-pa[1])*(pc[0]-pa[0]))/ (2*0.5*math.sqrt(sum(x*x for x in nn))*(W/2/R*0.95)**2+1e-12)
            g=int(120+120*min(1,nz))
            for y in range(int(min(a[1],b[1],c[1])),int(max(a[1],b[1],c[1]))+2):
                for x in range(int(min(a[0],b[0],c[0])),int(max(a[0],b[0],c[0]))+2):
                    w0=((b[0]-x)*(c[1]-y)-(b[1]-y)*(c[0]-x))/d
                    w1=((c[0]-x)*(a[1]-y)-(c[1]-y)*(a[0]-x))/d
                    w2=1-w0-w1
                    if w0>=0 and w1>=0 and w2>=0 and 0<=x<W and 0<=y<W:
                        z=w0*a[2]+w1*b[2]+w2*c[2]
                        if z>zb[y*W+x]: zb[y*W+x]=z; px[(y*W+x)*3:(y*W+x)*3+3]=bytes((g,g,g))
        for (i,j) in seams:
            p,q=P[i],P[j]; n=int(max(abs(q[0]-p[0]),abs(q[1]-p[1])))+1
            for k in range(n+1):
                t=k/n; x=int(p[0]+t*(q[0]-p[0])); y=int(p[1]+t*(q[1]-p[1])); z=p[2]+t*(q[2]-p[2])
                for dx in (0,1):
                  for dy in (0,1):
                    X,Y=x+dx,y+dy
                    if 0<=X<W and 0<=Y<W and z>=zb[Y*W+X]-0.02*R: px[(Y*W+X)*3:(Y*W+X)*3+3]=bytes((220,0,0))
        panels.append(px)
    # side by side
    out_px=bytearray()
    for y in range(W):
        for p in panels: out_px+=p[y*W*3:(y+1)*W*3]
    png(out,W*len(panels),W,out_px)
    print(len(seams),"seam edges")
render(sys.argv[1],sys.argv[2])
