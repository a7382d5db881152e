"""Triangle.intersect: blossom against Python bezier on the same triangles, in one run.

    pip install ./python numpy bezier      # in a virtual environment
    python benches/python/triangle_intersect_binding.py [pairs] [seed]

Pairs (default 200, seed 11): two quadratic triangles, each the reference quadratic triangle
(nodes (0,0) (1,0) (2,0) (0,1) (1,1) (0,2)) with every node moved by U(-0.15, 0.15), the second
shifted by U(0.2, 0.8) in x and y: they overlap along curved edges. Then 50 touching pairs:
straight triangles sharing an edge or a corner, and a copy of the first triangle (where the
regularized intersection is empty, or the triangle itself).

Each call is timed alone (time.perf_counter, best of 3, triangles built beforehand).
bezier's answer is checked against the certified enclosure [lo, hi] of the exact area
(blossom.CurvedRegion.from_triangle(..).intersection(..).area, not timed): it is counted wrong
when it raises, or when the sum of its polygons' areas lies outside [lo - 1e-12, hi + 1e-12]
(its areas are float sums; 1e-12 is some thousand times their rounding).
"""

import sys
import time
from collections import Counter

import numpy as np

import blossom
import bezier

BASE = np.array([[0.0, 1.0, 2.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0, 1.0, 2.0]])


def best(f, rounds=3):
    t = float("inf")
    out = None
    for _ in range(rounds):
        start = time.perf_counter()
        try:
            out = f()
        except Exception as e:  # bezier raises on some inputs: reported, not timed
            return None, e
        t = min(t, time.perf_counter() - start)
    return t, out


def pairs(count, seed):
    rng = np.random.default_rng(seed)
    for _ in range(count):
        n1 = BASE + rng.uniform(-0.15, 0.15, (2, 6))
        n2 = BASE + rng.uniform(-0.15, 0.15, (2, 6)) + rng.uniform(0.2, 0.8, (2, 1))
        yield "curved", (n1, 2), (n2, 2)
    for k in range(50):
        a = rng.integers(0, 8, 2).astype(float)
        b, c = a + [4.0, 0.0], a + [0.0, 4.0]
        t1 = (np.array([a, b, c]).T, 1)
        kind = k % 3
        if kind == 0:  # sharing the edge b-c
            t2 = (np.array([b + [0.0, 4.0], c, b]).T, 1)
        elif kind == 1:  # sharing the corner b
            t2 = (np.array([b, b + [3.0, 0.0], b + [0.0, 3.0]]).T, 1)
        else:  # the same triangle
            t2 = t1
        yield "touching", t1, t2


def main():
    count = int(sys.argv[1]) if len(sys.argv) > 1 else 200
    seed = int(sys.argv[2]) if len(sys.argv) > 2 else 11
    times = {"curved": ([], []), "touching": ([], [])}
    wrong = Counter()
    raised = Counter()
    total = Counter()
    for kind, (n1, d1), (n2, d2) in pairs(count, seed):
        total[kind] += 1
        o1, o2 = blossom.Triangle(n1, d1), blossom.Triangle(n2, d2)
        b1, b2 = bezier.Triangle(n1, d1), bezier.Triangle(n2, d2)
        lo, hi = blossom.CurvedRegion.from_triangle(o1).intersection(
            blossom.CurvedRegion.from_triangle(o2)).area
        t_ours, ours = best(lambda: o1.intersect(o2))
        assert t_ours is not None, ours
        ours_area = sum(p.area for p in ours)
        assert lo - 1e-12 <= ours_area <= hi + 1e-12
        t_theirs, theirs = best(lambda: b1.intersect(b2))
        if t_theirs is None:
            raised[(kind, type(theirs).__name__)] += 1
            wrong[kind] += 1
            continue
        times[kind][0].append(t_ours)
        times[kind][1].append(t_theirs)
        area = sum(p.area for p in theirs)
        if not (lo - 1e-12 <= area <= hi + 1e-12):
            wrong[kind] += 1
    print(f"blossom {blossom.__version__}, bezier {bezier.__version__}, seed {seed}")
    for kind in ("curved", "touching"):
        ours, theirs = times[kind]
        line = f"{kind}: {total[kind]} pairs, bezier wrong on {wrong[kind]}"
        if ours:
            so, st = sum(ours), sum(theirs)
            line += (f"; on the {len(ours)} bezier answered: blossom {so / len(ours) * 1e6:.1f} us"
                     f" per pair, bezier {st / len(ours) * 1e6:.1f} us, bezier time / blossom time {st / so:.3g}")
        print(line)
    for (kind, name), n in sorted(raised.items()):
        print(f"  bezier raised {name} on {n} {kind} pairs")


if __name__ == "__main__":
    main()
