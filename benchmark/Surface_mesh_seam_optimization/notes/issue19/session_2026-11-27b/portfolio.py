import csv,sys,math,itertools
files=sys.argv[1:]
data={}
for f in files:
    for r in csv.DictReader(open(f)):
        if r.get('uvm_valid')!='True' or r.get('bound_met')!='1': continue
        data.setdefault(f,{})[r['mesh']]=(float(r['seam_ratio']),float(r['seconds']),float(r['iterations']))
meshes=sorted(set.intersection(*[set(d) for d in data.values()]))
print(len(meshes),'meshes')
def summ(sel):
    rs=[min(data[f][m][0] for f in sel) for m in meshes]
    g=math.exp(sum(map(math.log,rs))/len(rs)); w=max(rs)
    return g,w,sum(r>1.05 for r in rs),sum(r>1.1 for r in rs), meshes[rs.index(w)]
for f in files: print(f.split('/')[-1], '%.4f %.3f >1.05:%d >1.1:%d %s'%summ([f]))
for k in range(2,len(files)+1):
    best=min(itertools.combinations(files,k),key=lambda s:summ(s)[0])
    print(k,[x.split('/')[-1] for x in best],'%.4f %.3f >1.05:%d >1.1:%d %s'%summ(best))
