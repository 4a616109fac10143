"""qmckit against SciPy in one run: time of each, and SciPy's time over qmckit's.

    python bench/bench_vs_scipy.py [--repeat 5] [--quick]

Cases (as in the issue): scrambled Sobol' 2^20 x 8, scrambled Halton 2^20 x 8, the
centered discrepancy of 4096 x 8 points, the L2-star discrepancy of 16384 x 8 points,
each with one worker and with all CPUs (``workers=-1``, where SciPy takes ``workers``),
and ``PoissonDisk(d=2).fill_space()`` at the same radius (so about the same density),
compared in points per second. The Sobol' case also times ``np.empty((n, d)).fill(0.5)``
against SciPy: the floor of any engine that returns a fresh array (its page faults and one
write), so the best ratio any engine could reach in that run, and qmckit's
``random(n, out=buf)`` into one array filled again and again (SciPy has no ``out=``). An
engine's time includes its construction (drawing the
scramble). Each case runs SciPy and qmckit alternately ``--repeat`` times and keeps each
side's best time, so a machine shared with other work penalizes both alike. A ratio
above 1 means qmckit is faster.

Time is the wall clock, or with ``--cpu-time`` the process's CPU time
(``time.process_time``: user and system time of all its threads, so page faults on a fresh
output count, but not the time other programs take on a shared machine). CPU time fits
the one-worker cases only (with more workers it adds the threads' times up), so
``--cpu-time`` skips the ``workers=-1`` rows; set ``OPENBLAS_NUM_THREADS=1`` so that no
idle BLAS thread spins and counts.
"""

import argparse
import os
import re
import time
import warnings

import numpy as np
from scipy.stats import qmc

import qmckit


CLOCK = time.perf_counter


def best_time(fn, repeat):
    best = float("inf")
    for _ in range(repeat):
        t = CLOCK()
        fn()
        best = min(best, CLOCK() - t)
    return best


def alternate(scipy_fn, qmckit_fn, repeat):
    """Best time of each, the two run alternately, and each side's last result."""
    s = q = float("inf")
    out = [None, None]

    def keep(k, fn):
        def run():
            out[k] = fn()
        return run

    for _ in range(repeat):
        s = min(s, best_time(keep(0, scipy_fn), 1))
        q = min(q, best_time(keep(1, qmckit_fn), 1))
    return s, q, out


def cases(quick):
    m = 16 if quick else 20
    n = 2**m
    d = 8
    default = qmckit.Sobol(1).randomizer
    yield (f"Sobol' 2^{m} x {d}, scrambled (SciPy LMS+shift)", f"{default} (default)",
           lambda: qmc.Sobol(d, rng=1).random(n),
           lambda: qmckit.Sobol(d, rng=1).random(n))
    # The floor of any engine that returns a fresh array: allocating the output and writing
    # it once (its page faults included), against the same SciPy call.
    yield (f"Sobol' 2^{m} x {d}, scrambled (SciPy LMS+shift)", "floor: np.empty + fill",
           lambda: qmc.Sobol(d, rng=1).random(n),
           lambda: np.empty((n, d)).fill(0.5))
    # qmckit's own answer to the floor: `out=`, a caller's array filled again (touched once,
    # so no page faults); SciPy's engines have no `out=`.
    buf = np.empty((n, d))
    buf.fill(0.0)
    yield (f"Sobol' 2^{m} x {d}, scrambled (SciPy LMS+shift)", f"{default}, random(out=)",
           lambda: qmc.Sobol(d, rng=1).random(n),
           lambda: qmckit.Sobol(d, rng=1).random(n, out=buf))
    for r in ("owen", "fast-owen", "lms", "xor"):
        if r != default:
            yield (f"Sobol' 2^{m} x {d}, scrambled (SciPy LMS+shift)", r,
                   lambda: qmc.Sobol(d, rng=1).random(n),
                   lambda r=r: qmckit.Sobol(d, rng=1, randomizer=r).random(n))
    for r in (default, "owen", "lms"):
        yield (f"Sobol' 2^{m} x {d}, scrambled, workers=-1 (SciPy ignores workers)", r,
               lambda: qmc.Sobol(d, rng=1).random(n),
               lambda r=r: qmckit.Sobol(d, rng=1, randomizer=r).random(n, workers=-1))
    yield (f"Halton 2^{m} x {d}, scrambled, workers=1", "perm (default)",
           lambda: qmc.Halton(d, rng=1).random(n),
           lambda: qmckit.Halton(d, rng=1).random(n))
    for w in (1, -1):
        yield (f"Halton 2^{m} x {d}, scrambled, workers={w}", "scipy-perm (SciPy's)",
               lambda w=w: qmc.Halton(d, rng=1).random(n, workers=w),
               lambda w=w: qmckit.Halton(d, rng=1, randomizer="scipy-perm").random(
                   n, workers=w))
    yield (f"Halton 2^{m} x {d}, scrambled, workers=1", "owen",
           lambda: qmc.Halton(d, rng=1).random(n),
           lambda: qmckit.Halton(d, rng=1, randomizer="owen").random(n))
    rng = np.random.default_rng(0)
    x_cd = qmc.Sobol(d, rng=rng).random(1024 if quick else 4096)
    x_l2 = qmc.Sobol(d, rng=rng).random(4096 if quick else 16384)
    for w in (1, -1):
        yield (f"CD discrepancy {len(x_cd)} x {d}, workers={w}", "",
               lambda w=w: qmc.discrepancy(x_cd, method="CD", workers=w),
               lambda w=w: qmckit.discrepancy(x_cd, method="CD", workers=w))
    for w in (1, -1):
        yield (f"L2-star discrepancy {len(x_l2)} x {d}, workers={w}", "",
               lambda w=w: qmc.discrepancy(x_l2, method="L2-star", workers=w),
               lambda w=w: qmckit.discrepancy(x_l2, method="L2-star", workers=w))
    r = 0.04 if quick else 0.02
    yield (f"PoissonDisk(d=2, radius={r}).fill_space(), points/s", "",
           lambda: qmc.PoissonDisk(2, radius=r, rng=1).fill_space(),
           lambda: qmckit.PoissonDisk(2, radius=r, rng=1).fill_space())


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--quick", action="store_true", help="smaller sizes (a smoke run)")
    ap.add_argument("--only", default="",
                    help="a regular expression: only the cases whose name matches it")
    ap.add_argument("--cpu-time", action="store_true",
                    help="time by the process's CPU time (one-worker rows only)")
    args = ap.parse_args()
    global CLOCK
    if args.cpu_time:
        CLOCK = time.process_time
    warnings.simplefilter("ignore", UserWarning)
    print(f"CPUs: {os.cpu_count()}; numpy {np.__version__}; "
          f"scipy {__import__('scipy').__version__}; qmckit {qmckit.__version__}")
    print(f"{'case':<62} {'qmckit variant':<24} {'SciPy s':>9} {'qmckit s':>9} {'ratio':>7}")
    for name, variant, s_fn, q_fn in cases(args.quick):
        if args.cpu_time and "workers=-1" in name:
            continue
        if args.only and not re.search(args.only, name):
            continue
        s, q, (s_out, q_out) = alternate(s_fn, q_fn, args.repeat)
        if name.endswith("points/s"):
            # Points per second: each side's set size over its time.
            ns, nq = len(s_out), len(q_out)
            variant = f"{ns} vs {nq} points"
            ratio = (nq / q) / (ns / s)
        else:
            ratio = s / q
        print(f"{name:<62} {variant:<24} {s:9.4f} {q:9.4f} {ratio:7.2f}", flush=True)


if __name__ == "__main__":
    main()
