import sys, re, collections
# stdin: lines "MESH name" then ROUND lines
mesh=None; R=collections.defaultdict(list)
for l in open(sys.argv[1]):
    if l.startswith('MESH'): mesh=l.split()[1]; continue
    m=re.match(r'ROUND (\S+) kind (\w) applied (\d) before (\S+) after (\S+) shorter (\d) it0 (\d+) improved_at (\d+) end (\d+)',l)
    if m: R[mesh].append(m.groups())
tot_all=tot_fail=tot_round=0
for mesh,rs in R.items():
    s=[]; fail=0; rounds=0
    for (p,k,a,b,af,sh,i0,ia,e) in rs:
        i0,ia,e=int(i0),int(ia),int(e); n=e-i0; rounds+=n
        if sh=='1': s.append(f"{k}+ {n} (improved at {ia-i0})")
        else: s.append(f"{k}= {n}"); fail+=n
    print(f"{mesh:26s} rounds' its {rounds:5d}, failing {fail:5d}: "+", ".join(s))
