#!/usr/bin/env python3
"""Seams of every subset of starts (the shortest feasible kept) from
per_start_40.csv, against the paper's code's (reference_optcuts.csv, bijective
rows). Ratios from the library's E_se: bunny_decim_noInputUV reads 0.43 here
(1.00 by uvmetrics, which merges its duplicated vertices), the same offset for
every subset. Usage: combos.py [reference_optcuts.csv]"""
import csv, math, os, sys
from itertools import combinations
here = os.path.dirname(os.path.abspath(__file__))
ref_path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, '../../../../../../shared/data/reference_optcuts.csv')
ref = {r[0]: float(r[4]) for r in csv.reader(l for l in open(ref_path) if not l.startswith('#'))
       if r[0] != 'mesh' and r[1] == '1'}
starts = {}
for r in csv.DictReader(l for l in open(os.path.join(here, 'per_start_40.csv')) if not l.startswith('#')):
    starts.setdefault(r['mesh'], {})[int(r['start'])] = (r['feasible'] == '1', float(r['e_se']), int(r['iterations']))
names = {0: 'first', 1: 'hold-price', 2: 'relaxed', 3: 'first-cut'}
gm = lambda v: math.exp(sum(map(math.log, v)) / len(v))
print(f"{'starts':32s} gm     worst  >1.05 >1.1  iterations of the slowest start / (first, hold-price) (geometric mean)")
for k in range(1, 5):
    for S in combinations(range(4), k):
        if 0 not in S: continue
        ratios, cost = [], []
        for m, st in starts.items():
            ratios.append(min(st[s][1] for s in S if st[s][0]) / ref[m])
            cost.append(max(st[s][2] for s in S) / max(st[0][2], st[1][2]))
        print(f"{'+'.join(names[s] for s in S):32s} {gm(ratios):.4f} {max(ratios):.3f}  {sum(x > 1.05 for x in ratios):3d} {sum(x > 1.1 for x in ratios):4d}   {gm(cost):.2f}")
