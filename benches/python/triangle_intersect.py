"""Python `bezier` (dhermes/bezier) Triangle.intersect on the triangle pairs of benches/region.rs.

Run the Rust bench first; it writes the pairs, the certified areas and its own time per pair:

    cargo bench -p blossom --bench region
    pip install bezier          # 2024.6.20, with numpy; its compiled speedups ship in the wheel
    python3 benches/python/triangle_intersect.py
    # and, interleaved with the library in the same run:
    cargo build --release -p blossom --example region_profile
    BLOSSOM_REGION_PROFILE=target/release/examples/region_profile python3 benches/python/triangle_intersect.py

The file is read from $CARGO_TARGET_DIR/region/triangles.json (else target/region/ of the
workspace), or from the directory given as the first argument:
{"degree": 2, "pairs": [{"triangles": [t1, t2], "area": [lo, hi], "loops": k, "seconds": s}, ...]},
each triangle six [x, y] nodes in the order of `blossom region` (p200, p110, p020, p101, p011,
p002), which is also bezier's order; "area" is the certified enclosure of the exact area of the
intersection, "seconds" the library's time for the pair (median of 5 runs) and
"seconds_first" its first call on freshly built regions (which also proves each region's
loops simple, a fact the library keeps on the region).

For each pair, bezier.Triangle.intersect (default strategy, geometric) is timed alone
(time.perf_counter around the call, the triangles built beforehand; the median of 5 calls).
Its answer is a list of curved polygons (or one of the triangles when one holds the other);
the sum of their areas is compared with the certified enclosure: wrong when it is outside by
more than 1e-9 (the triangles' boxes have areas near 1) or when bezier raises (counted by
exception type). Printed, and written to python_triangles.txt beside the input: the time per
pair of each side, the ratio, and the wrong answers.
"""

import json
import os
import statistics
import sys
import time
from collections import Counter
from pathlib import Path

import bezier
import numpy as np


def data_dir():
    if len(sys.argv) > 1:
        return Path(sys.argv[1])
    target = os.environ.get("CARGO_TARGET_DIR")
    if target:
        return Path(target) / "region"
    return Path(__file__).resolve().parents[2] / "target" / "region"


def triangle(nodes, degree):
    return bezier.Triangle(np.asfortranarray(np.array(nodes, dtype=float).T), degree=degree)


def area_of(pieces):
    return sum(piece.area for piece in pieces)


def main():
    directory = data_dir()
    data = json.loads((directory / "triangles.json").read_text())
    degree = data["degree"]
    pairs = data["pairs"]
    theirs, ours, ours_first = [], [], []
    exceptions = Counter()
    wrong = []
    for index, pair in enumerate(pairs):
        t1, t2 = (triangle(t, degree) for t in pair["triangles"])
        lo, hi = pair["area"]
        times = []
        result = None
        try:
            for _ in range(5):
                start = time.perf_counter()
                result = t1.intersect(t2)
                times.append(time.perf_counter() - start)
        except Exception as error:  # noqa: BLE001 - every failure is counted by type
            exceptions[type(error).__name__] += 1
            wrong.append(f"pair {index}: {type(error).__name__}: {error}")
            continue
        theirs.append(statistics.median(times))
        ours.append(pair["seconds"])
        ours_first.append(pair.get("seconds_first", pair["seconds"]))
        area = area_of(result)
        if area < lo - 1e-9 or area > hi + 1e-9:
            wrong.append(
                f"pair {index}: bezier area {area:.12f}, certified [{lo:.12f}, {hi:.12f}] "
                f"({len(result)} piece(s), certified {pair['loops']} loop(s))"
            )
    # The same pairs through blossom's Python package, when it is installed, timed in this run
    # beside bezier: the first call on fresh triangles (it builds and keeps their regions),
    # then the median of 5 calls.
    py_first, py_warm = [], []
    try:
        import blossom
    except ImportError:
        blossom = None
    if blossom is not None:
        for pair in pairs:
            t1, t2 = (
                blossom.Triangle(np.asfortranarray(np.array(t, dtype=float).T), degree=degree)
                for t in pair["triangles"]
            )
            start = time.perf_counter()
            t1.intersect(t2)
            py_first.append(time.perf_counter() - start)
            times = []
            for _ in range(5):
                start = time.perf_counter()
                t1.intersect(t2)
                times.append(time.perf_counter() - start)
            py_warm.append(statistics.median(times))

    # Interleaved with the library itself, when its profiling example is given
    # (BLOSSOM_REGION_PROFILE=target/release/examples/region_profile, built by
    # `cargo build --release -p blossom --example region_profile`): 5 rounds, each one pass of
    # bezier over the pairs and one run of the example over the same pairs, medians.
    interleaved = None
    profile = os.environ.get("BLOSSOM_REGION_PROFILE")
    if profile:
        import subprocess

        bezier_pairs = [tuple(triangle(t, degree) for t in p["triangles"]) for p in pairs]
        rounds_bezier, rounds_ours = [], []
        for _ in range(5):
            start = time.perf_counter()
            for t1, t2 in bezier_pairs:
                try:
                    t1.intersect(t2)
                except Exception:  # noqa: BLE001 - counted above
                    pass
            rounds_bezier.append((time.perf_counter() - start) / len(bezier_pairs))
            out = subprocess.run(
                [profile, "triangles", "200"], capture_output=True, text=True, check=True
            ).stdout
            rounds_ours.append(float(out.split(":")[1].split("us")[0]) * 1e-6)
        interleaved = (statistics.median(rounds_bezier), statistics.median(rounds_ours))

    # The degenerate pairs: bezier's answer against the certified one (not timed).
    degenerate = data.get("degenerate", [])
    degenerate_wrong = []
    for case in degenerate:
        t1, t2 = (triangle(t, degree) for t in case["triangles"])
        lo, hi = case["area"]
        try:
            result = t1.intersect(t2)
        except Exception as error:  # noqa: BLE001 - every failure is counted by type
            degenerate_wrong.append(f"{case['name']}: {type(error).__name__}: {error}")
            continue
        area = area_of(result)
        if area < lo - 1e-9 or area > hi + 1e-9:
            degenerate_wrong.append(
                f"{case['name']}: bezier area {area:.12f}, certified [{lo:.12f}, {hi:.12f}]"
            )
    mean = lambda xs: sum(xs) / len(xs) if xs else float("nan")
    lines = [
        f"pairs: {len(pairs)} quadratic triangle pairs (benches/region.rs)",
        f"bezier {bezier.__version__} Triangle.intersect: {mean(theirs) * 1e6:.1f} us per pair "
        f"(median of 5 calls each, averaged over {len(theirs)} pairs)",
        f"blossom triangle_intersection: {mean(ours) * 1e6:.2f} us per pair (same pairs, median "
        f"of 5 calls), {mean(ours_first) * 1e6:.2f} us for the first call on fresh regions",
        f"ratio bezier / blossom: {mean(theirs) / mean(ours):.2f} "
        f"(first calls: {mean(theirs) / mean(ours_first):.2f})",
        f"bezier wrong: {len(wrong)} of {len(pairs)} pairs "
        f"(area outside the certified enclosure by more than 1e-9, or an exception: "
        f"{dict(exceptions) or 'none'})",
    ] + (
        [
            f"interleaved in this run (5 rounds, medians): bezier {interleaved[0] * 1e6:.2f} us, "
            f"blossom region_profile {interleaved[1] * 1e6:.3f} us per pair, "
            f"ratio {interleaved[0] / interleaved[1]:.2f}"
        ]
        if interleaved
        else []
    ) + (
        [
            f"blossom (Python package) Triangle.intersect, same run: {mean(py_warm) * 1e6:.2f} us "
            f"per pair (median of 5 calls; ratio bezier / blossom {mean(theirs) / mean(py_warm):.2f}), "
            f"first call on fresh triangles {mean(py_first) * 1e6:.2f} us "
            f"(ratio {mean(theirs) / mean(py_first):.2f})"
        ]
        if py_warm
        else ["blossom's Python package is not installed: its line is skipped"]
    ) + ["  " + w for w in wrong] + [
        f"bezier wrong on the degenerate pairs: {len(degenerate_wrong)} of {len(degenerate)}"
    ] + ["  " + w for w in degenerate_wrong]
    text = "\n".join(lines) + "\n"
    print(text, end="")
    (directory / "python_triangles.txt").write_text(text)


if __name__ == "__main__":
    main()
