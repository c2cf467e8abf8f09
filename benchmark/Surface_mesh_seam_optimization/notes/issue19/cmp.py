import csv, sys, math
base={}
for l in open('/work/main/benchmark/results.md'):
    if l.startswith('| ') and not l.startswith('| mesh') and l.count('|')>20:
        c=[x.strip() for x in l.strip().strip('|').split('|')]
        try:
            if c[0] not in base: base[c[0]]=(float(c[11]),float(c[13]))  # E_se (uvm), ref E_se
        except: pass
rows=list(csv.DictReader(open(sys.argv[1])))
lb=[];ln=[];worst=(0,'')
for r in rows:
    m=r['mesh']; new=float(r['uvm_seam_length_normalized']); ref=float(r['ref_seam_norm'])
    b=base.get(m,(float('nan'),ref))[0]
    ok = r['bound_met']=='1' and r['uvm_flips']=='0' and r['uvm_overlap_pairs']=='0'
    print(f"{m:28s} base {b:7.3f} new {new:7.3f} ref {ref:7.3f}  base/ref {b/ref:5.3f} new/ref {new/ref:5.3f}  new/base {new/b:5.3f} {'OK' if ok else 'BAD'} it {r['iterations']} s {r['seconds']}")
    lb.append(math.log(b/ref)); ln.append(math.log(new/ref)); worst=max(worst,(new/ref,m))
print(f"geomean base {math.exp(sum(lb)/len(lb)):.4f} new {math.exp(sum(ln)/len(ln)):.4f}  worst new {worst}  n={len(ln)}")
