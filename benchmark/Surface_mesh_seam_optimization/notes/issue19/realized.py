import sys,re
lines=[l for l in open(sys.argv[1]) if l.startswith('SP it') or l.startswith('  prop') or l.startswith('SCAFFOLD') or l.startswith('FIRST')]
pred=0;prev=None;rows=[]
for l in lines:
    if l.startswith('FIRST'): break
    if l.startswith('SCAFFOLD'): prev=None; continue
    if l.startswith('  prop'):
        pred+=float(re.search(r'dsd (\S+)',l).group(1)); continue
    esd=float(re.search(r'esd (\S+)',l).group(1)); ese=float(re.search(r'ese (\S+)',l).group(1))
    sc=int(re.search(r' sc (\d)',l).group(1))
    if prev is not None: rows.append((prev[1],prev[0],esd-prev[0],pred,sc))
    m=re.search(r'op (\d) dsd (\S+) dse (\S+)',l)
    pred=float(m.group(2)) if m else 0
    prev=(esd,ese)
lo,hi=float(sys.argv[2]),float(sys.argv[3])
R=[r for r in rows if lo<=r[0]<hi]
sp=sum(r[3] for r in R); sr=sum(r[2] for r in R)
print(f"{sys.argv[1]} ese in [{lo},{hi}): {len(R)} stationary pts, predicted dE_SD {sp:.3f}, realized {sr:.3f}, ratio {sr/sp:.2f}")
