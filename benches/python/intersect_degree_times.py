"""Wall time of `blossom intersect` on random curve pairs and loops of degree 8 to 20.

Usage: python3 benches/python/intersect_degree_times.py [BINARY [DEGREE ...]]
(degrees default to 8 12 16 20; jobs of degree over 20 run with `--max-work 1e15`, so that
they are timed rather than refused by the default budget)
(BINARY defaults to target/release/blossom; build it with `cargo build --release -p blossom-cli`).

Curves have random coordinates k / q (|k| <= 20, q in {1, 2, 3, 7}) under `--arithmetic exact`
and six-decimal numbers in [-3, 3] under `--arithmetic f64` (seeded, so every run times the
same jobs). Each job runs once under the default budget; the line gives the wall time, the
exit code and the number of points (or the refusal). Whole-process times: they include start-up
(about 2 ms).
"""
import json
import random
import subprocess
import sys
import time

BINARY = sys.argv[1] if len(sys.argv) > 1 else "target/release/blossom"
DEGREES = [int(d) for d in sys.argv[2:]] or [8, 12, 16, 20]


def curve(rng, n, mode):
    if mode == "exact":
        return [[f"{rng.randint(-20, 20)}/{rng.choice([1, 2, 3, 7])}" for _ in range(2)]
                for _ in range(n + 1)]
    return [[repr(round(rng.uniform(-3, 3), 6)) for _ in range(2)] for _ in range(n + 1)]


def run(job, mode, degree):
    start = time.time()
    budget = ["--max-work", "1e15"] if degree > 20 else []
    p = subprocess.run([BINARY, "intersect", "--arithmetic", mode] + budget, input=json.dumps(job),
                       capture_output=True, text=True, timeout=120)
    elapsed = time.time() - start
    found = len(json.loads(p.stdout)["points"]) if p.returncode == 0 else p.stderr.strip()[:120]
    return elapsed, p.returncode, found


def main():
    rng = random.Random(7)
    for kind in ["curve-curve", "self"]:
        for n in DEGREES:
            for mode in ["exact", "f64"]:
                for _ in range(2):
                    if kind == "self":
                        job = {"kind": "self", "curve": curve(rng, n, mode)}
                    else:
                        job = {"kind": kind, "curves": [curve(rng, n, mode), curve(rng, n, mode)]}
                    elapsed, code, found = run(job, mode, n)
                    print(f"{kind:11} degree {n:2} {mode:5} {elapsed:6.2f} s  exit {code}  points {found}",
                          flush=True)


if __name__ == "__main__":
    main()
