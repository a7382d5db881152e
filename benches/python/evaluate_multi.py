"""Curve.evaluate_multi against Python bezier's, degrees 1..20, 1,000 parameters.

    python benches/python/evaluate_multi.py [--degrees 1-20] [--params 1000] [--rounds 7]
                                            [--dimension 2] [--seed 5] [--errors | --errors-only]

For each degree: one random planar curve (nodes uniform in [-1, 1]), 1,000 parameters uniform
in [0, 1] (the ends included), and the two calls `blossom.Curve(nodes, n).evaluate_multi(s)`
and `bezier.Curve(nodes, n).evaluate_multi(s)` timed in alternating rounds (each round the
mean over enough calls to take about 20 ms; the figure is the median round and the best).
Prints per degree the times in microseconds and bezier / blossom (> 1: blossom faster).

With --errors (--errors-only: without the timing) also the accuracy over the same degrees against the exact values
(fractions.Fraction, the doubles read exactly): the largest absolute error over 20 random
curves x 200 parameters per degree of blossom's evaluate_multi, of de Casteljau's algorithm
in float64 (x + s (y - x), the library's steps, in numpy) and of bezier's, and the ratios to
de Casteljau's. Node sets: uniform in [-1, 1], in [0, 1] and in [10, 11].

Needs numpy, bezier and an installed blossom (pip install ./python).
"""

import argparse
import math
import statistics
import sys
import time
from fractions import Fraction

import numpy as np

import bezier
import blossom


def degrees_arg(text):
    if "-" in text:
        lo, hi = text.split("-")
        return list(range(int(lo), int(hi) + 1))
    return [int(x) for x in text.split(",")]


def per_call(fn, target=0.02):
    """Mean seconds per call over about `target` seconds."""
    count = 1
    while True:
        start = time.perf_counter()
        for _ in range(count):
            fn()
        elapsed = time.perf_counter() - start
        if elapsed >= target:
            return elapsed / count
        count *= 2 if elapsed < target / 4 else max(2, math.ceil(target / max(elapsed, 1e-9)))


def timing(args):
    rng = np.random.default_rng(args.seed)
    s = np.concatenate([[0.0, 1.0], rng.uniform(0.0, 1.0, args.params - 2)])
    print(f"evaluate_multi, {args.params} parameters, dimension {args.dimension}, "
          f"{args.rounds} alternating rounds (median / best, us per call)")
    print(f"{'degree':>6} {'blossom':>16} {'bezier':>16} {'bezier/blossom':>15}")
    ratios = []
    for n in args.degrees:
        nodes = np.asfortranarray(rng.uniform(-1.0, 1.0, (args.dimension, n + 1)))
        ours, theirs = blossom.Curve(nodes, n), bezier.Curve(nodes, n)
        a, b = ours.evaluate_multi(s), theirs.evaluate_multi(s)
        assert np.allclose(a, b, rtol=0, atol=1e-13), n
        t_ours, t_theirs = [], []
        for _ in range(args.rounds):
            t_ours.append(per_call(lambda: ours.evaluate_multi(s)))
            t_theirs.append(per_call(lambda: theirs.evaluate_multi(s)))
        mo, mt = statistics.median(t_ours), statistics.median(t_theirs)
        ratios.append(mt / mo)
        print(f"{n:>6} {mo * 1e6:8.2f} / {min(t_ours) * 1e6:6.2f} {mt * 1e6:8.2f} / {min(t_theirs) * 1e6:6.2f}"
              f" {mt / mo:14.2f}x", flush=True)
    print(f"bezier / blossom over degrees {args.degrees[0]}..{args.degrees[-1]}: "
          f"least {min(ratios):.2f}x, median {statistics.median(ratios):.2f}x, most {max(ratios):.2f}x")


def exact_values(w, ts):
    """B(t) exactly for the doubles w (nodes of one coordinate) and ts, as Fractions."""
    n = len(w) - 1
    fw = [Fraction(x) for x in w]
    # The power basis, then Horner in integers: t = p / q (q a power of two).
    a = [math.comb(n, k) * sum((-1) ** (k - j) * math.comb(k, j) * fw[j] for j in range(k + 1))
         for k in range(n + 1)]
    den = 1
    for x in a:
        den = den * x.denominator // math.gcd(den, x.denominator)
    ints = [x.numerator * (den // x.denominator) for x in a]
    out = []
    for t in ts:
        p, q = Fraction(t).numerator, Fraction(t).denominator
        acc = ints[n]
        for k in range(n - 1, -1, -1):
            acc = acc * p + ints[k] * q ** (n - k)
        out.append(Fraction(acc, den * q ** n))
    return out


def de_casteljau(w, ts):
    """de Casteljau's algorithm in float64 with the library's steps x + t (y - x)."""
    level = np.tile(np.asarray(w, float)[:, None], (1, len(ts)))
    n = len(w) - 1
    for r in range(1, n + 1):
        for j in range(n + 1 - r):
            level[j] = level[j] + ts * (level[j + 1] - level[j])
    return level[0].copy()


def errors(args):
    rng = np.random.default_rng(args.seed + 1)
    for lo, hi in [(-1.0, 1.0), (0.0, 1.0), (10.0, 11.0)]:
        print(f"largest absolute error, 20 curves x 200 parameters per degree, nodes uniform in [{lo:g}, {hi:g}]")
        print(f"{'degree':>6} {'de Casteljau':>13} {'blossom':>10} {'bezier':>10} {'blossom/dC':>11} {'bezier/dC':>10}")
        worst_ratio = 0.0
        for n in args.degrees:
            worst = {"dc": 0.0, "ours": 0.0, "bezier": 0.0}
            for _ in range(20):
                w = rng.uniform(lo, hi, n + 1)
                ts = np.concatenate([[0.0, 0.5, 1.0], rng.uniform(0.0, 1.0, 197)])
                exact = exact_values(w, ts)
                nodes = np.asfortranarray(w[None, :])
                got = {
                    "dc": de_casteljau(w, ts),
                    "ours": blossom.Curve(nodes, n).evaluate_multi(ts)[0],
                    "bezier": bezier.Curve(nodes, n).evaluate_multi(ts)[0],
                }
                for k, v in got.items():
                    err = max(abs(float(Fraction(float(x)) - e)) for x, e in zip(v, exact))
                    worst[k] = max(worst[k], err)
            dc = worst["dc"]
            worst_ratio = max(worst_ratio, worst["ours"] / dc)
            print(f"{n:>6} {dc:13.2e} {worst['ours']:10.2e} {worst['bezier']:10.2e}"
                  f" {worst['ours'] / dc:11.2f} {worst['bezier'] / dc:10.2f}", flush=True)
        print(f"  largest blossom / de Casteljau ratio: {worst_ratio:.2f}")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--degrees", type=degrees_arg, default=list(range(1, 21)))
    parser.add_argument("--params", type=int, default=1000)
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--dimension", type=int, default=2)
    parser.add_argument("--seed", type=int, default=5)
    parser.add_argument("--errors", action="store_true")
    parser.add_argument("--errors-only", action="store_true")
    args = parser.parse_args()
    print(f"python {sys.version.split()[0]}, numpy {np.__version__}, bezier {bezier.__version__}")
    if not args.errors_only:
        timing(args)
    if args.errors or args.errors_only:
        errors(args)


if __name__ == "__main__":
    main()
