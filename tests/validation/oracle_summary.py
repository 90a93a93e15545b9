#!/usr/bin/env python3
"""Summarise hobsharp_oracle_campaign's CSV: per condition and class, the share of scenarios whose
library face agrees with the swept volume within 0.01 µm, max and rms differences, and every point
beyond 0.01 µm with where it lies and the oracle's flags."""
import csv, math, sys, collections

rows = [r for r in csv.DictReader(open(sys.argv[1])) if r.get('oracleTurnU') not in (None, '')]
tol = float(sys.argv[2]) if len(sys.argv) > 2 else 0.01
by = collections.defaultdict(list)
for r in rows:
    key = (r['grid'], r['cond'] if r['cond'] == 'nominal' else 'error/' + r['class'])
    by[key].append(r)
print("grid  condition            hobs  points  max|d| um   rms um   hobs>%.2gum  points>%.2gum" % (tol, tol))
for key in sorted(by):
    v = by[key]
    hobs = collections.defaultdict(list)
    for r in v: hobs[r['index']].append(abs(float(r['diffUm'])))
    d = [abs(float(r['diffUm'])) for r in v]
    bad = sum(1 for h in hobs.values() if max(h) > tol)
    print("%-5s %-20s %4d %7d %10.3g %9.3g %6d/%d %8d" % (key[0], key[1], len(hobs), len(v), max(d),
          math.sqrt(sum(x * x for x in d) / len(d)), bad, len(hobs), sum(x > tol for x in d)))
print()
hg = collections.defaultdict(lambda: collections.defaultdict(list))
for r in rows: hg[(r['gash'], r['hand'])][r['index']].append(abs(float(r['diffUm'])))
print("by gash and hand (every condition):", {"%s/%s" % k: "%d hobs, %d beyond %.2g um, max %.3g um" % (
    len(v), sum(max(x) > tol for x in v.values()), tol, max(max(x) for x in v.values())) for k, v in sorted(hg.items())})
print()
flags = collections.Counter()
for r in rows:
    if r['cond'] == 'error' and float(r['rho']) > float(r['wheelRadius']) + 1e-6: flags['error: contact beyond the rim (rho > d_w/2)'] += 1
    for f in ['atRangeEnd', 'atWindowEnd', 'wall', 'lowerEntry']:
        if r[f] == '1': flags[f] += 1
    if int(r['localMinima']) > 1: flags['several local minima'] += 1
    if float(r['uWheel']) > float(r['uTip']) + 1e-6: flags['wheel point past the tip'] += 1
    if float(r['uWheel']) < float(r['uRoot']) - 1e-6: flags['wheel point past the root'] += 1
print("flags:", dict(flags))
rim = collections.defaultdict(set)
for r in rows:
    if float(r['rho']) > float(r['wheelRadius']) + 1e-6: rim[(r['grid'], r['class'], r['cond'])].add(r['index'])
print("hobs with a contact beyond the rim:", {k: len(v) for k, v in sorted(rim.items())})
turn = sorted({(r['index'], r['turnRadius']) for r in rows if float(r['turnRadius']) > 0})
print("hobs whose profile turns (library's wheelEdge):", turn)
print()
print("points beyond %.2g um:" % tol)
for r in rows:
    if abs(float(r['diffUm'])) > tol:
        print({k: r[k] for k in ['index', 'class', 'gash', 'hand', 'cond', 'grid', 'i', 'j', 'r', 'tLib', 'tOracle', 'diffUm',
                                 'rho', 'wheelRadius', 'uWheel', 'uRoot', 'uTip', 'turnRadius', 'localMinima', 'wall',
                                 'atRangeEnd', 'crossAtLibUm']})
