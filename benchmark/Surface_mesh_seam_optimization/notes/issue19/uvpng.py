import sys, zlib, struct, math
def load(p):
    V=[];T=[];F=[]
    for l in open(p):
        s=l.split()
        if not s: continue
        if s[0]=='v': V.append(tuple(map(float,s[1:4])))
        elif s[0]=='vt': T.append(tuple(map(float,s[1:3])))
        elif s[0]=='f':
            c=[x.split('/') for x in s[1:]]
            F.append(([int(a[0])-1 for a in c],[int(a[1])-1 for a in c]))
    return V,T,F
def png(path,W,H,px):
    raw=b''.join(b'\x00'+bytes(px[y*W*3:(y+1)*W*3]) for y in range(H))
    def ch(t,d): c=struct.pack('>I',len(d))+t+d; return c+struct.pack('>I',zlib.crc32(t+d)&0xffffffff)
    open(path,'wb').write(b'\x89PNG\r\n\x1a\n'+ch(b'IHDR',struct.pack('>IIBBBBB',W,H,8,2,0,0,0))+ch(b'IDAT',zlib.compress(raw,6))+ch(b'IEND',b''))
def main(obj,out,W=700):
    V,T,F=load(obj)
    xs=[t[0] for t in T]; ys=[t[1] for t in T]
    x0,x1,y0,y1=min(xs),max(xs),min(ys),max(ys)
    s=(W-20)/max(x1-x0,y1-y0)
    H=int((y1-y0)*s)+20
    P=lambda t:((T[t][0]-x0)*s+10,(y1-T[t][1])*s+10)
    px=bytearray([255]*(W*H*3))
    def put(x,y,c):
        if 0<=x<W and 0<=y<H: px[(y*W+x)*3:(y*W+x)*3+3]=bytes(c)
    for fv,ft in F:
        a,b,c=[P(t) for t in ft]
        mnx=int(min(a[0],b[0],c[0]));mxx=int(max(a[0],b[0],c[0]))+1
        mny=int(min(a[1],b[1],c[1]));mxy=int(max(a[1],b[1],c[1]))+1
        d=(b[0]-a[0])*(c[1]-a[1])-(b[1]-a[1])*(c[0]-a[0])
        if d==0: continue
        for y in range(mny,mxy+1):
            for x in range(mnx,mxx+1):
                w0=((b[0]-x)*(c[1]-y)-(b[1]-y)*(c[0]-x))/d
                w1=((c[0]-x)*(a[1]-y)-(c[1]-y)*(a[0]-x))/d
                w2=1-w0-w1
                if w0>=0 and w1>=0 and w2>=0:
                    i=(y*W+x)*3
                    if 0<=x<W and 0<=y<H:
                        if px[i]==255: px[i:i+3]=bytes((200,210,230))
                        else: px[i:i+3]=bytes((250,120,0))  # overlap
    # edges: boundary/seam edges in red, others light
    E={}
    for fi,(fv,ft) in enumerate(F):
        for k in range(3):
            e=(fv[k],fv[(k+1)%3]); E.setdefault((min(e),max(e)),[]).append((ft[k],ft[(k+1)%3],fv[k]))
    def line(p,q,c):
        n=int(max(abs(q[0]-p[0]),abs(q[1]-p[1])))+1
        for i in range(n+1):
            t=i/n; put(int(p[0]+t*(q[0]-p[0])),int(p[1]+t*(q[1]-p[1])),c)
    for e,l in E.items():
        seam=len(l)==1
        if len(l)==2:
            (a1,b1,v1),(a2,b2,v2)=l
            m1={v1:a1}; 
            seam=not ({T[a1],T[b1]}=={T[a2],T[b2]})
        for (a,b,v) in l:
            line(P(a),P(b),(220,0,0) if seam else (150,160,190))
    png(out,W,H,px)
main(sys.argv[1],sys.argv[2])
