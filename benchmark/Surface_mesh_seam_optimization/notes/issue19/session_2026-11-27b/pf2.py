import csv,math,re
N='/work/main/benchmark/Surface_mesh_seam_optimization/notes/issue19/'
ref={}
for r in csv.reader(open('/work/shared/data/reference_optcuts.csv')):
    if r and not r[0].startswith('#') and r[0]!='mesh':
        if r[1]=='1' or r[0] not in ref: ref[r[0]]=float(r[4])
s1={};v2={}
for l in open(N+'full_v2_cmp.txt'):
    t=l.split()
    if len(t)>6 and t[1]=='base': s1[t[0]]=float(t[2]); v2[t[0]]=float(t[4])
two={r['mesh']:float(r['uvm_seam_length_normalized']) for r in csv.DictReader(open(N+'full_two_starts.csv'))}
fb={}
for f in ('fb1a','fb1b'):
    for r in csv.reader(open('/tmp/t19/runs/%s.csv'%f)):
        if r[8]=='True': fb[r[0]]=float(r[4])
ms=sorted(set(s1)&set(v2)&set(fb)&set(two))
def summ(name,vals):
    rs=[vals[m]/ref[m] for m in ms]; g=math.exp(sum(map(math.log,rs))/len(rs)); w=max(rs)
    print('%-28s n %d geomean %.4f worst %.3f (%s) >1.05: %d >1.1: %d'%(name,len(ms),g,w,ms[rs.index(w)],sum(r>1.05 for r in rs),sum(r>1.1 for r in rs)))
summ('start1 alone',s1); summ('v2 alone',v2); summ('fb alone',fb); summ('two starts (current)',two)
summ('min(start1,fb)',{m:min(s1[m],fb[m]) for m in ms})
summ('min(two,fb) = three starts',{m:min(two[m],fb[m]) for m in ms})
for m in ms:
    if fb[m] < two[m]-1e-6: print('  fb better: %-24s %.3f -> %.3f'%(m,two[m]/ref[m],fb[m]/ref[m]))
print()
sw={m:min(s1[m],fb[m]) for m in ms}
for m in ms:
    if sw[m] > two[m]+1e-6: print('  swap worse: %-24s %.3f -> %.3f'%(m,two[m]/ref[m],sw[m]/ref[m]))
# times
tw={}
for l in open('/work/main/benchmark/results.md'):
    t=[x.strip() for x in l.split('|')]
    if len(t)>5 and t[1] in ms and t[3].replace('.','').isdigit(): tw.setdefault(t[1],(float(t[3]),float(t[4])))
ft={}
for f in ('fb1a','fb1b'):
    for r in csv.reader(open('/tmp/t19/runs/%s.csv'%f)): ft[r[0]]=float(r[1])
rat=sorted(ft[m]/tw[m][0] for m in ms if m in tw)
print('fb time / current wall: median %.2f p90 %.2f max %.2f'%(rat[len(rat)//2],rat[9*len(rat)//10],rat[-1]))
print('median current wall %.2f, median fb %.2f, ref median %.2f'%(sorted(tw[m][0] for m in ms)[len(ms)//2], sorted(ft[m] for m in ms)[len(ms)//2], sorted(tw[m][1] for m in ms)[len(ms)//2]))
print('missing', set(two)-set(ms))
