"""Python `bezier` (dhermes/bezier) on the random cubic pairs of benches/intersect.rs.

Run the Rust bench first; it writes the pairs and its answers:

    cargo bench -p blossom --bench intersect
    pip install bezier          # 2024.6.20, with numpy; its compiled speedups ship in the wheel
    python3 benches/python/intersect_pairs.py

The files are read from $CARGO_TARGET_DIR/intersect/ (else target/intersect/ of the
workspace), or from the directory given as the first argument: pairs.json
({"seed", "pairs": [[p, q], ...]}, p and q four [x, y] each) and answers.json
({"answers": [{"ours": [[s, t], ...], "lyon": [...]}, ...]}, "ours" the certified answer).

For each pair, bezier.Curve.intersect with its default strategy (geometric: subdivision to a
linearisation tolerance, then Newton) is timed alone (time.perf_counter around the call, the
curves built beforehand). Exceptions are caught and counted by type (their pairs count neither
in the time nor in the comparison). Printed, and written to python_summary.txt beside the
inputs: the time per pair (mean and median), the exceptions, the pairs whose number of
intersections differs from the certified one (too few / too many), and the largest
|s - s_bezier|, |t - t_bezier| over pairs with the right count (each certified point matched to
the nearest bezier point).
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
        return Path(target) / "intersect"
    return Path(__file__).resolve().parents[2] / "target" / "intersect"


def curve(points):
    nodes = np.asfortranarray(np.array(points, dtype=np.float64).T)
    return bezier.Curve(nodes, degree=len(points) - 1)


def compare(ours, theirs, stats):
    """Counts a wrong number of points, else the parameter differences of matched points."""
    if len(theirs) < len(ours):
        stats["too_few"] += 1
        stats["points_too_few"] += len(ours) - len(theirs)
    elif len(theirs) > len(ours):
        stats["too_many"] += 1
        stats["points_too_many"] += len(theirs) - len(ours)
    else:
        for s, t in ours:
            bs, bt = min(theirs, key=lambda x: np.hypot(x[0] - s, x[1] - t))
            stats["max_ds"] = max(stats["max_ds"], abs(bs - s))
            stats["max_dt"] = max(stats["max_dt"], abs(bt - t))


def main():
    folder = data_dir()
    pairs = json.loads((folder / "pairs.json").read_text())["pairs"]
    answers = json.loads((folder / "answers.json").read_text())["answers"]
    if len(pairs) != len(answers):
        sys.exit(f"{folder}: {len(pairs)} pairs but {len(answers)} answers")
    times = []
    failures = Counter()
    stats = Counter(max_ds=0.0, max_dt=0.0)
    for (p, q), answer in zip(pairs, answers):
        a, b = curve(p), curve(q)
        start = time.perf_counter()
        try:
            st = a.intersect(b)
        except Exception as e:  # bezier raises on too many candidates, tangencies, ...
            failures[f"{type(e).__name__}: {str(e)[:60]}"] += 1
            continue
        times.append(time.perf_counter() - start)
        theirs = [(float(s), float(t)) for s, t in st.T]
        compare([tuple(x) for x in answer["ours"]], theirs, stats)
    lines = [
        f"python bezier {bezier.__version__}: {len(pairs)} pairs from {folder}",
        f"bezier Curve.intersect: {1e6 * statistics.fmean(times):.1f} us per pair (mean), "
        f"{1e6 * statistics.median(times):.1f} us (median), {len(times)} pairs answered",
        f"bezier exceptions: {sum(failures.values())}"
        + "".join(f"\n  {n} x {kind}" for kind, n in failures.most_common()),
        f"bezier wrong count: {stats['too_few'] + stats['too_many']} of {len(times)} pairs "
        f"({stats['too_few']} too few, missing {stats['points_too_few']} points; "
        f"{stats['too_many']} too many, {stats['points_too_many']} extra points)",
        f"bezier on pairs with the right count: max |s - s_bezier| = {stats['max_ds']:.3e}, "
        f"max |t - t_bezier| = {stats['max_dt']:.3e}",
    ]
    text = "\n".join(lines)
    print(text)
    (folder / "python_summary.txt").write_text(text + "\n")


if __name__ == "__main__":
    main()
