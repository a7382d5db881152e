"""Long computations release the GIL: a spinning Python thread advances during the call.

With a long switch interval the interpreter hands the GIL to another thread only when the
holder releases it (or after the interval), so a spinning thread's counter advances across a
short call exactly when the call releases the GIL; the control, a C builtin that keeps it,
shows no progress."""

import math
import sys
import threading
import time

import numpy as np

import blossom


def progress_during(fn):
    count = 0
    stop = False

    def spin():
        nonlocal count
        while not stop:
            count += 1

    old = sys.getswitchinterval()
    sys.setswitchinterval(0.2)
    worker = threading.Thread(target=spin)
    try:
        worker.start()
        time.sleep(0.01)  # the spinner takes the GIL; this thread is back after the interval
        before = count
        fn()
        after = count
    finally:
        stop = True
        worker.join()
        sys.setswitchinterval(old)
    return after - before


def test_the_control_keeps_the_gil():
    assert progress_during(lambda: math.factorial(20000)) == 0


def test_restrict_curves_releases_the_gil():
    nodes = np.random.default_rng(3).uniform(-1, 1, (1_000_000, 2, 4))
    # The best of three calls: the spinning thread must also be scheduled by the system.
    assert max(progress_during(lambda: blossom.restrict_curves(nodes, 0.25, 0.75)) for _ in range(3)) > 0


def test_exact_intersections_release_the_gil():
    rng = np.random.default_rng(5)
    p = blossom.Curve(np.round(rng.uniform(0, 1, (2, 12)) * 1e6) / 1e6, 11)
    q = blossom.Curve(np.round(rng.uniform(0, 1, (2, 12)) * 1e6) / 1e6, 11)
    assert max(progress_during(lambda: p.intersections(q)) for _ in range(3)) > 0
