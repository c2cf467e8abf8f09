import re,sys,csv
blocks={};cur=None
for l in open(sys.argv[1]):
    if l.startswith('=='): cur=l.split()[1]; blocks[cur]=[]; continue
    if cur and l.startswith('['): blocks[cur].append(l.split())
tab={r['mesh']:r for r in csv.DictReader(open(sys.argv[2]))}
for m,L in blocks.items():
    def val(x,k): return x[x.index(k)+1]
    tags=[x[0] for x in L]
    rel=[x for x in L if x[0]=='[relaxed]']
    rs=[x for x in L if x[0]=='[relaxed-scaffold]']
    fc=[x for x in L if x[0]=='[firstcut]']
    fi=[i for i,x in enumerate(L) if x[0]=='[first]']
    # drop nested first before [firstcut]
    if fc:
        j=tags.index('[firstcut]'); fi=[i for i in fi if i>j]
    firsts=[L[i] for i in fi]
    nested_rs = int(val(rs[0],'it'))-int(val(rel[0],'it')) if rs and rel else None
    outer=[x for x in firsts if int(val(x,'it'))!=nested_rs]
    o=outer[0] if outer else None
    oit=int(val(o,'it')) if o else None
    ose=float(val(o,'se')) if o else None
    rit=int(val(rel[0],'it')) if rel else None
    rst=val(rel[0],'status') if rel else None
    rse=float(val(rs[0],'se')) if rs else None
    k=tab.get(m,{})
    print(f"{m:28s} first {oit} {ose} | relaxed free {rit} st {rst} ratio {rit/oit if rit and oit else '-':} scaffold se {rse} | kept {k.get('start')} {k.get('seam_length_normalized')}")
