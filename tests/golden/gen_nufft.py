#!/usr/bin/env python3
"""Golden files for qmckit's NUFFT periodogram, from two independent oracles: numpy's direct
complex-exponential sums and the finufft package (Flatiron Institute, PyPI `finufft`).

Run: `pip install finufft numpy && python3 tests/golden/gen_nufft.py` (from anywhere).
Deterministic (numpy `default_rng(20)`); writes tests/golden/nufft_<set>_n4096_k256.txt,
read by tests/suite/spectrum.rs (`cargo test` never runs Python).

Two sets of N = 4096 points in [0, 1)^2, given as 0.32 fixed-point numerators (x = u / 2^32,
exact in binary64): `white` (independent uniform) and `grid` (the 64 x 64 grid of cell
centres moved by at most 0.05 cells: near-lattice power up to about N at the dual lattice,
the hard case for a tolerance relative to max P).

Each file holds `point u v` lines, then `power kx ky P_numpy P_finufft` lines at 3601
frequencies of [-256, 256]^2: every k with |kx|, |ky| <= 12, and 2976 more drawn uniformly
from the square (numpy's generator), each once. P = |sum_j exp(-2 pi i k.x_j)|^2 / N.
numpy sums the phases in complex128 (the reference); finufft's `nufft2d1` (isign = -1,
eps = 1e-14 requested, modes ordered -K..K) covers the whole square, and its worst
difference from numpy over the listed frequencies is printed in the header.
"""
from pathlib import Path

import finufft
import numpy as np

N, K = 4096, 256
rng = np.random.default_rng(20)


def white():
    return rng.integers(0, 2**32, size=(N, 2), dtype=np.uint64)


def grid():
    n = 64
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    c = (np.stack([i.ravel(), j.ravel()], axis=1) + 0.5 + rng.uniform(-0.05, 0.05, (N, 2))) / n
    return np.floor(c * 2**32).astype(np.uint64)


def frequencies():
    near = [(kx, ky) for ky in range(-12, 13) for kx in range(-12, 13)]
    seen = set(near)
    far = []
    while len(far) < 2976:
        k = tuple(int(v) for v in rng.integers(-K, K + 1, size=2))
        if k not in seen:
            seen.add(k)
            far.append(k)
    return np.array(near + far, dtype=np.int64)


def numpy_power(x, ks):
    out = np.empty(len(ks))
    for a in range(0, len(ks), 256):
        kk = ks[a : a + 256].astype(float)
        out[a : a + 256] = np.abs(np.exp(-2j * np.pi * (kk @ x.T)).sum(axis=1)) ** 2 / N
    return out


def finufft_power(x):
    t = 2 * np.pi * x
    tx, ty = np.ascontiguousarray(t[:, 0]), np.ascontiguousarray(t[:, 1])
    c = np.ones(N, dtype=np.complex128)
    f = finufft.nufft2d1(tx, ty, c, (2 * K + 1, 2 * K + 1), eps=1e-14, isign=-1)
    return np.abs(f) ** 2 / N  # f[ix, iy], modes -K..K (first index is x)


ks = frequencies()
for name, make in [("white", white), ("grid", grid)]:
    u = make()
    x = u.astype(float) / 2**32
    ref = numpy_power(x, ks)
    full = finufft_power(x)
    fin = full[ks[:, 0] + K, ks[:, 1] + K]
    worst = np.max(np.abs(fin - ref)) / N
    out = Path(__file__).resolve().parent / f"nufft_{name}_n{N}_k{K}.txt"
    with out.open("w") as f:
        f.write(f"# {name}: N = {N}, K = {K}, numpy {np.__version__}, finufft {finufft.__version__}\n")
        f.write(f"# max |P_finufft - P_numpy| / N over the listed frequencies: {worst:.3e}\n")
        f.write(f"# max P over the whole square (finufft): {float(full.max())!r}\n")
        for p in u:
            f.write(f"point {int(p[0])} {int(p[1])}\n")
        for (kx, ky), a, b in zip(ks, ref, fin):
            f.write(f"power {int(kx)} {int(ky)} {float(a)!r} {float(b)!r}\n")
    print(f"wrote {out}: finufft vs numpy {worst:.3e} of N")
