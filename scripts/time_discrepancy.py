#!/usr/bin/env python3
"""Time qmckit's L2 discrepancies against SciPy's on the same points, single-threaded.

Usage (from the repository root):

    python3 scripts/time_discrepancy.py [--rounds R] [--n N] [--seed S] [--big-m M] [--exe PATH]

For d in (2, 8) it draws N (default 4096) seeded uniform points and times, on the same
points, `scipy.stats.qmc.discrepancy(x, method=..., workers=1)` for SciPy's four methods
(L2-star, CD, WD, MD; in this process) and qmckit single-threaded (the example
`examples/time_l2.rs`, built here with `cargo build --release --features analysis --example time_l2`; each
metric 3 times in a one-thread rayon pool). The two alternate for R rounds (default 5) so
that load on a shared machine hits both alike; each reports its best time. It prints a
markdown table of milliseconds, the ratio SciPy / qmckit, the relative difference of the
values and whether that difference is within SciPy's own rounding error (its plain double
sums of n^2 terms err by up to about 4 n eps max(c, 1) on the squared value, c the constant
term: up to ~1e-8 relative for CD in 2D; qmckit's values are checked to 1e-12 against exact
sums by tests/golden_discrepancy.rs). Then it times qmckit's L2-star of 2^M (default 2^20)
uniform points in 2D on one thread (no SciPy: its O(n^2) would take hours).
`--exe PATH` times a previously built copy of the example instead of building it (to
compare two versions of qmckit under the same conditions).
"""
import argparse
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np
from scipy.stats import qmc

ROOT = Path(__file__).resolve().parent.parent
EXE = ROOT / "target" / "release" / "examples" / "time_l2"
METHODS = [("L2-star", "l2-star"), ("CD", "cd"), ("WD", "wd"), ("MD", "md")]


def qmckit(exe, points, reps, metrics):
    """{metric: (best seconds, value)} from the example `exe`, on `points` written as text."""
    with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as f:
        np.savetxt(f, points, fmt="%.17g")
        path = f.name
    try:
        out = subprocess.run(
            [str(exe), path, str(points.shape[1]), str(reps), *metrics],
            check=True, capture_output=True, text=True,
        ).stdout
    finally:
        Path(path).unlink()
    res = {}
    for line in out.splitlines():
        name, secs, value = line.split()
        res[name] = (float(secs), float(value))
    return res


def scipy_best(points, method, reps):
    best, value = float("inf"), None
    for _ in range(reps):
        t = time.perf_counter()
        value = qmc.discrepancy(points, method=method, workers=1)
        best = min(best, time.perf_counter() - t)
    return best, value


# The constant term c of the squared value of each method, as a function of d.
CONSTANT = {"L2-star": lambda d: 3.0 ** -d, "CD": lambda d: (13 / 12) ** d,
            "WD": lambda d: (4 / 3) ** d, "MD": lambda d: (19 / 12) ** d}


def within_scipy_error(method, n, d, ours, theirs):
    """|ours - theirs| on the squared value within 1e-12 relative plus SciPy's error model."""
    sq = (lambda v: v * v) if method == "L2-star" else (lambda v: v)
    eps = np.finfo(float).eps
    tol = 1e-12 * abs(sq(theirs)) + 4 * n * eps * max(CONSTANT[method](d), 1.0)
    return abs(sq(ours) - sq(theirs)) <= tol


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--n", type=int, default=4096)
    ap.add_argument("--seed", type=int, default=20240601)
    ap.add_argument("--big-m", type=int, default=20)
    ap.add_argument("--exe", type=Path, default=None)
    args = ap.parse_args()
    exe = args.exe
    if exe is None:
        subprocess.run(["cargo", "build", "--release", "--quiet", "--features", "analysis",
                        "--example", "time_l2"],
                       cwd=ROOT, check=True)
        exe = EXE
    rng = np.random.default_rng(args.seed)
    print(f"n = {args.n}, best of {args.rounds} alternating rounds, one thread each\n")
    print("| d | method | SciPy ms | qmckit ms | ratio | rel. diff | within SciPy's error |")
    print("|---|---|---:|---:|---:|---:|---|")
    for d in (2, 8):
        x = rng.random((args.n, d))
        best_q, best_sp = {}, {}
        for _ in range(args.rounds):
            for name, (t, v) in qmckit(exe, x, 3, [m for _, m in METHODS]).items():
                best_q[name] = min(best_q.get(name, (t, v)), (t, v))
            for method, _ in METHODS:
                t, v = scipy_best(x, method, 1)
                best_sp[method] = min(best_sp.get(method, (t, v)), (t, v))
        for method, name in METHODS:
            (t_sp, v_sp), (t_q, v_q) = best_sp[method], best_q[name]
            rel = abs(v_q - v_sp) / abs(v_sp)
            ok = "yes" if within_scipy_error(method, args.n, d, v_q, v_sp) else "NO"
            print(f"| {d} | {method} | {t_sp * 1e3:.2f} | {t_q * 1e3:.3f} | "
                  f"{t_sp / t_q:.1f}x | {rel:.1e} | {ok} |")
    n_big = 1 << args.big_m
    big = rng.random((n_big, 2))
    t_big, v_big = qmckit(exe, big, 3, ["l2-star"])["l2-star"]
    print(f"\nqmckit L2-star, 2^{args.big_m} uniform points in 2D, one thread: "
          f"{t_big * 1e3:.1f} ms (value {v_big:.6e})")


if __name__ == "__main__":
    main()
