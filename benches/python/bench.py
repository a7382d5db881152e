"""blossom's Python package against Python bezier, on the same arrays in one run.

    python benches/python/bench.py [--pairs 500] [--seed 7] [--no-rust] [--only batch]

Prints, each figure with its ratio:
  * Curve.intersect on random cubic pairs, blossom vs bezier (whole set, best of 5 runs);
  * evaluate_multi with 1,000 parameters, subdivide and specialize, blossom vs bezier's classes
    and vs bezier's compiled routines called directly (bezier._speedup);
  * the batch restriction of 100,000 cubics (blossom.restrict_curves) vs the Rust call
    (benches/python/batch_restrict.rs, run through cargo unless --no-rust);
  * accuracy: every blossom intersect answer vs the exact answer's correctly rounded doubles
    (Curve.intersections, exact path), and where bezier's answers differ from them.

Needs numpy, bezier and an installed blossom (pip install ./python).
"""

import argparse
import os
import subprocess
import sys
import time

import numpy as np

import blossom
import bezier

try:
    from bezier import _speedup
except ImportError:  # bezier without its compiled part
    _speedup = None


def best(fn, runs=5, inner=1):
    """Best wall time of `runs` runs of `inner` calls, per call, in seconds."""
    out = float("inf")
    for _ in range(runs):
        start = time.perf_counter()
        for _ in range(inner):
            fn()
        out = min(out, (time.perf_counter() - start) / inner)
    return out


def report(name, ours, theirs, unit="us"):
    scale = {"us": 1e6, "ms": 1e3}[unit]
    print(f"{name:<46} blossom {ours * scale:10.2f} {unit}   bezier {theirs * scale:10.2f} {unit}   ratio {theirs / ours:6.2f}x")


def random_cubics(rng, count):
    return [np.asfortranarray(rng.uniform(0.0, 1.0, (2, 4))) for _ in range(count)]


def intersections(args, rng):
    ps, qs = random_cubics(rng, args.pairs), random_cubics(rng, args.pairs)
    ours = [(blossom.Curve(p, 3), blossom.Curve(q, 3)) for p, q in zip(ps, qs)]
    theirs = [(bezier.Curve(p, 3), bezier.Curve(q, 3)) for p, q in zip(ps, qs)]

    bezier_failures = 0

    def run_theirs():
        nonlocal bezier_failures
        bezier_failures = 0
        for a, b in theirs:
            try:
                a.intersect(b)
            except Exception:
                bezier_failures += 1

    t_ours = best(lambda: [a.intersect(b) for a, b in ours])
    t_theirs = best(run_theirs)
    found = sum(a.intersect(b).shape[1] for a, b in ours)
    print(f"{args.pairs} random cubic pairs in [0, 1]^2 (seed {args.seed}), {found} intersections")
    report("Curve.intersect, all pairs", t_ours, t_theirs, "ms")
    report("Curve.intersect, per pair", t_ours / args.pairs, t_theirs / args.pairs)

    # Accuracy: the exact answer's correctly rounded doubles.
    ours_differ = bezier_count = bezier_value = 0
    worst_ulps = 0.0
    for (a, b), (ba, bb) in zip(ours, theirs):
        st = a.intersect(b)
        rec = a.intersections(b)
        exact = [(p.s.value, p.t.value) for p in rec.points]
        for o in rec.overlaps:
            exact += [(o.s[0].value, o.t[0].value), (o.s[1].value, o.t[1].value)]
        exact.sort()
        if [tuple(c) for c in st.T.tolist()] != exact:
            ours_differ += 1
        try:
            theirs_st = ba.intersect(bb)
        except Exception:
            continue
        theirs_sorted = sorted(tuple(c) for c in theirs_st.T.tolist())
        if len(theirs_sorted) != len(exact):
            bezier_count += 1
            continue
        if theirs_sorted != exact:
            bezier_value += 1
            for (s, t), (es, et) in zip(theirs_sorted, exact):
                for x, e in ((s, es), (t, et)):
                    if x != e:
                        worst_ulps = max(worst_ulps, abs(x - e) / np.spacing(abs(e) if e else 1e-300))
    print(f"  blossom answers differing from the exact answer's correctly rounded doubles: {ours_differ} of {args.pairs}")
    print(f"  bezier: {bezier_failures} raised, {bezier_count} with another count, {bezier_value} with other doubles (worst {worst_ulps:.0f} ulps)")


def evaluation(rng):
    nodes = np.asfortranarray(rng.uniform(-1, 1, (2, 4)))
    ours, theirs = blossom.Curve(nodes, 3), bezier.Curve(nodes, 3)
    s_vals = np.linspace(0.0, 1.0, 1000)
    assert np.allclose(ours.evaluate_multi(s_vals), theirs.evaluate_multi(s_vals), atol=1e-15)
    inner = 2000
    report("evaluate_multi, 1,000 parameters (classes)", best(lambda: ours.evaluate_multi(s_vals), inner=inner), best(lambda: theirs.evaluate_multi(s_vals), inner=inner))
    report("subdivide (classes)", best(ours.subdivide, inner=inner * 10), best(theirs.subdivide, inner=inner * 10))
    report("specialize(0.25, 0.75) (classes)", best(lambda: ours.specialize(0.25, 0.75), inner=inner * 10), best(lambda: theirs.specialize(0.25, 0.75), inner=inner * 10))
    if _speedup is not None:
        report("evaluate_multi vs bezier._speedup.evaluate_multi", best(lambda: ours.evaluate_multi(s_vals), inner=inner), best(lambda: _speedup.evaluate_multi(nodes, s_vals), inner=inner))
        report("subdivide vs _speedup.subdivide_nodes_curve", best(ours.subdivide, inner=inner * 10), best(lambda: _speedup.subdivide_nodes_curve(nodes), inner=inner * 10))
        report("specialize vs _speedup.specialize_curve", best(lambda: ours.specialize(0.25, 0.75), inner=inner * 10), best(lambda: _speedup.specialize_curve(nodes, 0.25, 0.75), inner=inner * 10))


def batch(args, rng):
    count = 100_000
    c_order = rng.uniform(-1, 1, (count, 2, 4))
    point_major = np.ascontiguousarray(c_order.transpose(0, 2, 1)).transpose(0, 2, 1)
    out_c, out_p = np.empty_like(c_order), np.empty((count, 4, 2)).transpose(0, 2, 1)
    runs = 20
    figures = {
        "point after point (the Rust call's layout)": best(lambda: blossom.restrict_curves(point_major, 0.25, 0.75), runs),
        "point after point, out=": best(lambda: blossom.restrict_curves(point_major, 0.25, 0.75, out=out_p), runs),
        "C order": best(lambda: blossom.restrict_curves(c_order, 0.25, 0.75), runs),
        "C order, out=": best(lambda: blossom.restrict_curves(c_order, 0.25, 0.75, out=out_c), runs),
    }
    assert np.array_equal(out_c, out_p)
    rust = {}
    if not args.no_rust:
        root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
        cmd = ["cargo", "run", "-q", "--release", "-p", "blossom-python", "--example", "batch_restrict", "--features", "rust-bench"]
        try:
            text = subprocess.run(cmd, cwd=root, check=True, capture_output=True, text=True).stdout
            rust = {k: float(v) * 1e-9 for k, v in (line.split() for line in text.splitlines())}
        except (OSError, subprocess.CalledProcessError) as e:
            print(f"  (the Rust side did not run: {e})")
    print(f"batch restriction of {count:,} planar cubics to [0.25, 0.75], best of {runs}:")
    for name, t in figures.items():
        line = f"  blossom.restrict_curves, {name:<44} {t * 1e3:7.3f} ms"
        if "rust_batch_ns" in rust:
            line += f"   {t / rust['rust_batch_ns']:5.2f}x the Rust call"
        print(line)
    if rust:
        print(f"  Rust RestrictionMap::restrict_arrays on [[f64; 2]; 4]: {rust['rust_batch_ns'] * 1e3:7.3f} ms; on 200,000 1-D rows: {rust['rust_rows_ns'] * 1e3:7.3f} ms")
        if "rust_c_order_ns" in rust:
            print(f"  Rust, the binding's C-order route (64 curves copied to points, restricted, copied back): {rust['rust_c_order_ns'] * 1e3:7.3f} ms")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--pairs", type=int, default=500)
    parser.add_argument("--seed", type=int, default=7)
    parser.add_argument("--no-rust", action="store_true")
    parser.add_argument("--only", choices=["intersect", "evaluate", "batch"], help="run one of the three parts")
    args = parser.parse_args()
    rng = np.random.default_rng(args.seed)
    print(f"python {sys.version.split()[0]}, numpy {np.__version__}, bezier {bezier.__version__}, blossom {blossom.__version__}")
    if args.only in (None, "intersect"):
        intersections(args, rng)
    if args.only in (None, "evaluate"):
        evaluation(rng)
    if args.only in (None, "batch"):
        batch(args, rng)


if __name__ == "__main__":
    main()
