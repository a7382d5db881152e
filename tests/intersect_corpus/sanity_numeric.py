#!/usr/bin/env python3
"""A floating-point sanity check of cases.json, independent of truth.py's exact machinery
(it proves nothing; it catches a generator bug): every point satisfies P(s) ~ Q(t) and its
coordinates match (to 1e-6 of the largest coordinate); for the random families, the roots
agree with mpmath's polyroots at 60 digits, and the number of interior intersections with the
crossings of 600-segment polylines.
Prints every disagreement and "bad N" at the end (0 expected)."""
import json, os, sys
from fractions import Fraction as F
import mpmath as mp
mp.mp.dps = 60
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from truth import bernstein_power
d = json.load(open(os.path.join(HERE, 'cases.json')))['cases']
def num(x): return F(x) if not isinstance(x, str) else F(x)
def bez(ctrl, u):
    pts=[mp.mpf(c.numerator)/c.denominator for c in ctrl]
    n=len(pts)-1
    return mp.fsum(mp.binomial(n,i)*pts[i]*u**i*(1-u)**(n-i) for i in range(n+1))
bad=0
for c in d:
    j=c['job']; e=c['expected']
    if j['kind']=='roots':
        cs=[num(x) for x in j['control_points']]
        if e['identically_zero']: continue
        a=bernstein_power(cs)
        while a and a[-1]==0: a.pop()
        if len(a)<=1:
            if e['roots']: print('ROOTS?', c['name']); bad+=1
            continue
        if 'random' not in c['family']: continue
        rts=mp.polyroots([mp.mpf(x.numerator)/x.denominator for x in reversed(a)], maxsteps=500, extraprec=2000)
        real=sorted(set(round(float(mp.re(r)),9) for r in rts if abs(mp.im(r))<1e-20 and -1e-15<=mp.re(r)<=1+1e-15))
        mine=[round(r['t']['value'],9) for r in e['roots']]
        if real!=mine: print('ROOTS', c['name'], real, mine); bad+=1
        continue
    if j['kind']=='curve-curve':
        P=[[num(x) for x in p] for p in j['curves'][0]]; Q=[[num(x) for x in p] for p in j['curves'][1]]
    else:
        P=[[num(x) for x in p] for p in j['curve']]; Q=P
    # The tolerance scales with the curves' size (the f64-scaled families reach 1e180).
    size=max(1, max(abs(x) for pt in P+Q for x in pt))
    for p in e['points']:
        s=mp.mpf(p['s']['value']); t=mp.mpf(p['t']['value'])
        dx=bez([q[0] for q in P],s)-bez([q[0] for q in Q],t); dy=bez([q[1] for q in P],s)-bez([q[1] for q in Q],t)
        if abs(dx)+abs(dy)>1e-6*size: print('POINT', c['name'], p['s']['value'], p['t']['value'], float(dx), float(dy)); bad+=1
        px=bez([q[0] for q in P],s)
        if abs(px - p['point'][0]['value'])>1e-9*(1+abs(px)): print('COORD', c['name']); bad+=1
    if c['family'].split('/')[1].startswith('random') or 'higher' in c['family'] or 'high-degree' in c['family'] or 'line-cubic' in c['family']:
        # polyline crossing count
        N=600
        def poly(C): 
            return [(float(bez([q[0] for q in C],mp.mpf(i)/N)), float(bez([q[1] for q in C],mp.mpf(i)/N))) for i in range(N+1)]
        A=poly(P); B=A if j['kind']=='self' else poly(Q)
        def cross(p,q,r,s_):
            def o(a,b,c): return (b[0]-a[0])*(c[1]-a[1])-(b[1]-a[1])*(c[0]-a[0])
            return o(p,q,r)*o(p,q,s_)<0 and o(r,s_,p)*o(r,s_,q)<0
        # grid acceleration skipped: N small
        cnt=0
        for i in range(N):
            for k in range(N):
                if j['kind']=='self' and k<=i+1: continue
                a0,a1=A[i],A[i+1]; b0,b1=B[k],B[k+1]
                if max(a0[0],a1[0])<min(b0[0],b1[0]) or max(b0[0],b1[0])<min(a0[0],a1[0]) or max(a0[1],a1[1])<min(b0[1],b1[1]) or max(b0[1],b1[1])<min(a0[1],a1[1]): continue
                if cross(a0,a1,b0,b1): cnt+=1
        interior=[p for p in e['points'] if 0<p['s']['value']<1 and 0<p['t']['value']<1]
        if cnt!=len(interior): print('COUNT', c['name'], cnt, len(e['points'])); bad+=1
print('bad', bad)
