#!/usr/bin/env python3
"""Golden file for qmckit::analysis::spectrum from numpy's complex exponentials.

Run: `python3 tests/golden/gen_spectrum.py` (numpy only; from anywhere). Deterministic
(numpy `default_rng(2026)`); writes tests/golden/spectrum_random_n50_k7.txt, read by
tests/spectrum.rs (`cargo test` never runs Python).

The file holds 50 uniform random points in [0, 1)^2 (float repr, `point x y` lines) and the
periodogram P(k) = |sum_j exp(-2 pi i (kx x_j + ky y_j))|^2 / N for every integer frequency
in [-7, 7]^2 (`power kx ky P` lines), computed as one complex matrix of phases
exp(-2j pi K X^T) summed by numpy in complex128: an implementation independent of qmckit's
(which factors the phases per axis and reduces them to [0, 1) turns first).
"""
from pathlib import Path

import numpy as np

K = 7
N = 50
rng = np.random.default_rng(2026)
x = rng.random((N, 2))
freqs = np.array([(kx, ky) for ky in range(-K, K + 1) for kx in range(-K, K + 1)], dtype=float)
phases = np.exp(-2j * np.pi * (freqs @ x.T))  # (frequencies, points)
power = np.abs(phases.sum(axis=1)) ** 2 / N

out = Path(__file__).resolve().parent / f"spectrum_random_n{N}_k{K}.txt"
with out.open("w") as f:
    f.write(f"# periodogram of {N} numpy default_rng(2026) points, K = {K}, numpy {np.__version__}\n")
    for p in x:
        f.write(f"point {float(p[0])!r} {float(p[1])!r}\n")
    for (kx, ky), p in zip(freqs, power):
        f.write(f"power {int(kx)} {int(ky)} {float(p)!r}\n")
print(f"wrote {out}")
