"""The Python call's own cost on the region booleans: blossom's Python package against the
library's Rust call (benches/python/region_call.rs), on the same numbers, in one run.

    python benches/python/region_call.py [--no-rust] [--passes 3] [--font PATH] [--glyphs a,O,...]
    python benches/python/region_call.py --callgrind [--calls 200]

Cases (each written to a text file that the Rust side reads, numbers as repr of doubles):
  * square_circle: the union of the square [0, 2]^2 (4 lines) and a 4-cubic circle of
    centre (1.3, 1.1) and radius 1 (handles 0.5523 r), in general position;
  * square_circle_joins: the same with the circle centred at (1, 1): its joins lie exactly on
    the square's edges (the degenerate placement of issue 45);
  * glyph_<name>: overlap removal (simplify, nonzero) of glyphs of DejaVu Sans, their outlines
    decomposed as fontTools' BasePen decomposes them (lines, quadratics at implied on-curve
    points), composites decomposed.

Each case is timed two ways on both sides (the best of 7 rounds of the mean over a round of
about 20 ms):
  * kept: the operation alone on regions built once (CurvedRegion.simplify() or .union(b);
    the Rust simplify() or boolean());
  * built: the regions built from the control points, then the operation (Python: a
    CurvedRegion from a list of loops of 2 x N float64 arrays; Rust: Region::from_f64).
and the ratio Python / Rust is printed for each, with the Rust time of the work estimate
(simplify_work or boolean_work), which the Python call computes first when the regions hold
more than 8 curves or a curve of degree over 4 (column "est").

With --callgrind (needs valgrind), each case's operation is instead run `calls` times on kept
regions in a Python process under callgrind, and the instructions per call are printed (load
does not change them): the extension's method as Python calls it (pyo3's trampoline, inclusive:
argument handling, the work estimate, the library call, the BooleanResult), the library call
inside it (blossom::region::boolean::simplify or ::boolean), and their difference, the
binding's own cost (the deallocation of each result, which holds the RegionResult whose drop
the Rust loop pays too, is not in either count).

Needs numpy, fontTools and an installed blossom; cargo for the Rust side
(`cargo run --release -p blossom-python --example region_call --features rust-bench`).
"""

import argparse
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

import blossom

K = 0.5523


def square(x, y, s):
    c = [(x, y), (x + s, y), (x + s, y + s), (x, y + s)]
    return [[c[i], c[(i + 1) % 4]] for i in range(4)]


def circle(cx, cy, r):
    m = K * r
    return [
        [(cx + r, cy), (cx + r, cy + m), (cx + m, cy + r), (cx, cy + r)],
        [(cx, cy + r), (cx - m, cy + r), (cx - r, cy + m), (cx - r, cy)],
        [(cx - r, cy), (cx - r, cy - m), (cx - m, cy - r), (cx, cy - r)],
        [(cx, cy - r), (cx + m, cy - r), (cx + r, cy - m), (cx + r, cy)],
    ]


def glyph_loops(font, name):
    """The glyph's contours as loops of curves (lists of points), decomposed as BasePen does
    (closePath and endPath close a contour by a line; contours without a curve dropped)."""
    from fontTools.pens.basePen import BasePen

    class Collect(BasePen):
        def __init__(self, glyph_set):
            super().__init__(glyph_set)
            self.loops, self.loop, self.start = [], None, None

        def _moveTo(self, pt):
            self.loop, self.start = [], pt

        def _current(self):
            return self._getCurrentPoint()

        def _lineTo(self, pt):
            self.loop.append([self._current(), pt])

        def _qCurveToOne(self, p1, p2):
            self.loop.append([self._current(), p1, p2])

        def _curveToOne(self, p1, p2, p3):
            self.loop.append([self._current(), p1, p2, p3])

        def _closePath(self):
            cur = self._current()
            if cur is not None and tuple(cur) != tuple(self.start):
                self.loop.append([cur, self.start])
            if self.loop:
                self.loops.append(self.loop)
            self.loop = None

        _endPath = _closePath

    glyph_set = font.getGlyphSet()
    pen = Collect(glyph_set)
    glyph_set[name].draw(pen)
    return [[[(float(x), float(y)) for x, y in c] for c in lp] for lp in pen.loops]


def cases(args):
    out = [
        ("square_circle", "union", [[square(0.0, 0.0, 2.0)], [circle(1.3, 1.1, 1.0)]]),
        ("square_circle_joins", "union", [[square(0.0, 0.0, 2.0)], [circle(1.0, 1.0, 1.0)]]),
    ]
    try:
        from fontTools.ttLib import TTFont
    except ImportError:
        print("fontTools is not installed: the glyph cases are skipped")
        return out
    font = TTFont(args.font)
    cmap = font.getBestCmap()
    for name in args.glyphs.split(","):
        glyph = cmap.get(ord(name), name) if len(name) == 1 else name
        out.append((f"glyph_{glyph}", "simplify", [glyph_loops(font, glyph)]))
    return out


def write(cases_, path):
    with open(path, "w") as f:
        for name, op, regions in cases_:
            f.write(f"case {name} {op} nonzero\n")
            for loops in regions:
                for lp in loops:
                    f.write("loop\n")
                    for c in lp:
                        f.write("c " + " ".join(repr(v) for p in c for v in p) + "\n")
                f.write("end\n")


def time_call(f):
    start = time.perf_counter()
    f()
    once = max(time.perf_counter() - start, 1e-9)
    inner = int(min(max(0.02 / once, 1), 100_000))
    best = float("inf")
    for _ in range(7):
        start = time.perf_counter()
        for _ in range(inner):
            f()
        best = min(best, (time.perf_counter() - start) / inner)
    return best * 1e9


def python_side(cases_):
    out = {}
    for name, op, regions in cases_:
        # Each region a list of loops of 2 x N arrays.
        arrays = [[[np.array(c, dtype=float).T.copy() for c in lp] for lp in loops]
                  for loops in regions]

        def build():
            return [blossom.CurvedRegion(a) for a in arrays]

        regions_built = build()
        if op == "simplify":
            a = regions_built[0]
            if hasattr(a, "simplify"):
                kept = lambda: a.simplify()
                built = lambda: build()[0].simplify()
            else:  # before CurvedRegion.simplify: the union with the empty region
                empty = blossom.CurvedRegion([])
                kept = lambda: a.union(empty)
                built = lambda: build()[0].union(empty)
        else:
            a, b = regions_built
            kept = lambda: getattr(a, op)(b)

            def built():
                x, y = build()
                return getattr(x, op)(y)
        out[name] = (time_call(kept), time_call(built))
    return out


def rust_side(path):
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    cmd = ["cargo", "run", "--quiet", "--release", "-p", "blossom-python", "--example",
           "region_call", "--features", "rust-bench", "--", path]
    text = subprocess.run(cmd, cwd=root, check=True, capture_output=True, text=True).stdout
    out = {}
    for line in text.splitlines():
        words = line.split()
        if words and words[0] == "rust":
            out[words[1]] = (float(words[2]), float(words[3]), float(words[4]))
    return out


CALLGRIND_SCRIPT = """
import pickle, sys
import numpy as np
import blossom
name, op, regions, calls = pickle.load(open(sys.argv[1], "rb"))
built = [blossom.CurvedRegion([[np.array(c, dtype=float).T.copy() for c in lp] for lp in loops])
         for loops in regions]
if op != "simplify":
    run = lambda: getattr(built[0], op)(built[1])
elif hasattr(built[0], "simplify"):
    run = lambda: built[0].simplify()
else:  # a blossom before CurvedRegion.simplify: the union with the empty region
    empty = blossom.CurvedRegion([])
    run = lambda: built[0].union(empty)
run()
for _ in range(calls):
    run()
"""


def callgrind(cases_, calls):
    import pickle
    import re

    symbols = {
        "method": r"pyo3::impl_::trampoline::trampoline ",
        "library": r"blossom::region::boolean::(simplify|boolean) ",
    }
    print(f"instructions per call (callgrind, {calls} calls on kept regions after one more)")
    print(f"{'case':<24} {'method':>11} {'library':>11} {'binding':>9} {'ratio':>6}")
    with tempfile.TemporaryDirectory() as d:
        script = os.path.join(d, "run.py")
        with open(script, "w") as f:
            f.write(CALLGRIND_SCRIPT)
        for name, op, regions in cases_:
            data = os.path.join(d, "case.pickle")
            with open(data, "wb") as f:
                pickle.dump((name, op, regions, calls), f)
            out = os.path.join(d, "callgrind.out")
            subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}",
                            sys.executable, script, data], check=True, capture_output=True)
            text = subprocess.run(["callgrind_annotate", "--inclusive=yes", out], check=True,
                                  capture_output=True, text=True).stdout
            counts = {}
            for key, pattern in symbols.items():
                for line in text.splitlines():
                    if re.search(r"[?]+:" + pattern, line):
                        counts[key] = int(line.split()[0].replace(",", "")) / (calls + 1)
                        break
            m, lib = (counts.get(k, float("nan")) for k in ("method", "library"))
            print(f"{name:<24} {m:11.0f} {lib:11.0f} {m - lib:9.0f} {m / lib:6.3f}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--no-rust", action="store_true")
    parser.add_argument("--font", default="/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf")
    parser.add_argument("--glyphs", default="a,O,g,ampersand,Aring,B")
    parser.add_argument("--passes", type=int, default=3)
    parser.add_argument("--callgrind", action="store_true")
    parser.add_argument("--calls", type=int, default=200)
    args = parser.parse_args()
    cs = cases(args)
    if args.callgrind:
        callgrind(cs, args.calls)
        return
    # The two sides alternate (a Rust pass, a Python pass, ...) and each figure is the best
    # over the passes: on a shared machine the load drifts between the two processes.
    best = lambda old, new: {k: tuple(map(min, zip(old[k], v))) if k in old else v
                             for k, v in new.items()}
    rust, py = {}, {}
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "cases.txt")
        write(cs, path)
        for _ in range(args.passes):
            if not args.no_rust:
                rust = best(rust, rust_side(path))
            py = best(py, python_side(cs))
    print(f"blossom {blossom.__version__}; times in us per call (best of {args.passes} passes, "
          f"each the best of 7 rounds of ~20 ms)")
    print(f"{'case':<24} {'py kept':>9} {'rust kept':>9} {'ratio':>6}   "
          f"{'py built':>9} {'rust built':>10} {'ratio':>6}   {'est':>7}")
    for name, _, _ in cs:
        pk, pb = py[name]
        if name in rust:
            rk, rb, re = rust[name]
            print(f"{name:<24} {pk / 1e3:9.1f} {rk / 1e3:9.1f} {pk / rk:6.2f}   "
                  f"{pb / 1e3:9.1f} {rb / 1e3:10.1f} {pb / rb:6.2f}   {re / 1e3:7.1f}")
        else:
            print(f"{name:<24} {pk / 1e3:9.1f} {'':>9} {'':>6}   {pb / 1e3:9.1f}")


if __name__ == "__main__":
    main()
