import csv, math, statistics
full={r['mesh']:r for r in csv.DictReader(open('/tmp/full_t.csv'))}
r0={r['mesh']:r for r in csv.DictReader(open('/tmp/r0/table.csv'))}
rows=[]
for m,f in full.items():
    if m not in r0: continue
    ref=float(f['ref_seam_norm'])
    a=float(f['seam_length_normalized'])/ref; b=float(r0[m]['seam_length_normalized'])/ref
    ta=float(f['seconds']); tb=float(r0[m]['seconds'])
    rows.append((m,a,b,ta,tb,r0[m]['bound_met'],r0[m]['status']))
n=len(rows)
g=lambda xs: math.exp(sum(math.log(x) for x in xs)/len(xs))
print(n,"meshes; lib seam ratio geomean: rounds 6 %.4f, rounds 0 %.4f"%(g([r[1] for r in rows]),g([r[2] for r in rows])))
print("worst: %.3f vs %.3f"%(max(r[1] for r in rows),max(r[2] for r in rows)), "above 1.05:", sum(r[1]>1.05 for r in rows), sum(r[2]>1.05 for r in rows))
print("median s: %.2f vs %.2f; per-mesh time ratio geomean %.3f"%(statistics.median(r[3] for r in rows),statistics.median(r[4] for r in rows),g([r[4]/r[3] for r in rows])))
for r in sorted(rows,key=lambda r:r[2]/r[1]): print("%-26s %.3f %.3f  %7.2f %7.2f %s %s"%r)
