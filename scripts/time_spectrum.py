#!/usr/bin/env python3
"""Side-by-side timing of qmckit's periodogram against finufft (one thread) and against
direct sums (qmckit's own and numpy's), on the same points.

Run: `pip install finufft numpy && python3 scripts/time_spectrum.py` from the repository
root (builds `examples/time_spectrum` in release mode). Prints one line per case with the
best of REPS runs and the ratios. The NUFFTs run at the same requested tolerance 1e-9
(qmckit's is |P - P_exact| <= 1e-9 N; finufft's `eps` is a relative l2 error of the sums).
"""
import os
import subprocess
import tempfile
import time

import finufft
import numpy as np

REPS = 5
TOL = 1e-9
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def ours(path, k, methods, threads=None):
    env = dict(os.environ)
    if threads:
        env["RAYON_NUM_THREADS"] = str(threads)
    exe = os.path.join(ROOT, "target", "release", "examples", "time_spectrum")
    out = subprocess.run(
        [exe, path, str(k), str(REPS), str(TOL), *methods], env=env, check=True, capture_output=True, text=True
    ).stdout
    return {line.split()[0]: float(line.split()[1]) for line in out.splitlines()}


def finufft_time(x, k):
    t = 2 * np.pi * x
    tx, ty = np.ascontiguousarray(t[:, 0]), np.ascontiguousarray(t[:, 1])
    c = np.ones(len(x), dtype=np.complex128)
    best = np.inf
    for _ in range(REPS):
        t0 = time.perf_counter()
        f = finufft.nufft2d1(tx, ty, c, (2 * k + 1, 2 * k + 1), eps=TOL, isign=-1, nthreads=1)
        np.abs(f) ** 2 / len(x)
        best = min(best, time.perf_counter() - t0)
    return best


def numpy_direct(x, k):
    # One row of frequencies at a time: exp(-2 pi i (kx x + ky y)) factored per axis.
    t0 = time.perf_counter()
    ks = np.arange(-k, k + 1)
    ex = np.exp(-2j * np.pi * np.outer(ks, x[:, 0]))  # (2K+1, N)
    ey = np.exp(-2j * np.pi * np.outer(ks, x[:, 1]))
    s = ey @ ex.T  # S[ky, kx]
    np.abs(s) ** 2 / len(x)
    return time.perf_counter() - t0


subprocess.run(["cargo", "build", "--release", "--features", "analysis", "--example", "time_spectrum"],
               cwd=ROOT, check=True)
rng = np.random.default_rng(1)
with tempfile.TemporaryDirectory() as tmp:
    for n, k in [(4096, 256), (65536, 512)]:
        x = rng.random((n, 2))
        path = os.path.join(tmp, f"p{n}.txt")
        np.savetxt(path, x, fmt="%.17g")
        one = ours(path, k, ["nufft"], threads=1)["nufft"]
        two = ours(path, k, ["nufft"])["nufft"]
        fin = finufft_time(x, k)
        line = f"N={n} K={k}: qmckit nufft {one:.4f} s (1 thread), {two:.4f} s (all threads); finufft {fin:.4f} s (1 thread): finufft/qmckit {fin / one:.2f} (1 thread)"
        if n == 4096:
            direct = ours(path, k, ["direct"])["direct"]
            nd = numpy_direct(x, k)
            line += f"; qmckit direct {direct:.4f} s, numpy direct {nd:.4f} s: direct/nufft {direct / two:.1f} (same threads)"
        print(line, flush=True)
