#!/usr/bin/env python3
"""Regenerate the golden files in this folder from oracles qmckit did not write.

  * SciPy's `scipy.stats.qmc.Halton(d, scramble=False)` (float64; starts at index 0).
  * Exact radical inverses from Python's `fractions.Fraction`, straight from the
    definition phi_b(i) = sum_j d_j b^-j.
  * SciPy's `qmc.Sobol(d, scramble=False, bits=32)` (Gray-code order), as exact integers
    (bits=32 outputs are k / 2^32). Large outputs are stored as FNV-1a-64 digests of their
    little-endian u32 bytes, plus the first points in full for debugging.

Run: `pip install scipy==1.17.1 && python3 tests/golden/gen.py` (from the repo root or
anywhere). Output is deterministic; `cargo test` only reads the committed files, it never
runs Python.
"""
from fractions import Fraction
from pathlib import Path

import numpy as np
import scipy
from scipy.stats import qmc

HERE = Path(__file__).resolve().parent


def write_halton(d: int, n: int) -> None:
    pts = qmc.Halton(d, scramble=False).random(n)
    path = HERE / f"scipy_halton_d{d}_n{n}.txt"
    with path.open("w") as f:
        f.write(f"# scipy {scipy.__version__} numpy {np.__version__}: "
                f"qmc.Halton({d}, scramble=False).random({n}); one point per line\n")
        for row in pts:
            f.write(" ".join(repr(float(x)) for x in row) + "\n")


def radical_inverse(base: int, i: int) -> Fraction:
    x, w = Fraction(0), Fraction(1, base)
    while i:
        i, d = divmod(i, base)
        x += d * w
        w /= base
    return x


def write_radical_inverses() -> None:
    path = HERE / "exact_radical_inverse.txt"
    indices = list(range(0, 64)) + [100, 1000, 4095, 4096, 65_535, 65_536, 123_456_789,
                                    2**31 - 1, 2**31, 3_000_000_000, 2**32 - 2, 2**32 - 1]
    with path.open("w") as f:
        f.write("# base index numerator denominator: phi_base(index) = numerator/denominator "
                "in lowest terms (Python fractions)\n")
        for base in (2, 3, 5, 7, 11, 31, 8161):
            for i in indices:
                x = radical_inverse(base, i)
                f.write(f"{base} {i} {x.numerator} {x.denominator}\n")


def fnv1a64(values) -> int:
    h = 0xCBF29CE484222325
    for v in values:
        for byte in int(v).to_bytes(4, "little"):
            h = ((h ^ byte) * 0x100000001B3) & 0xFFFFFFFFFFFFFFFF
    return h


def sobol_u32(d: int, n: int) -> np.ndarray:
    pts = qmc.Sobol(d, scramble=False, bits=32).random(n)
    ints = np.ldexp(pts, 32)
    assert np.all(ints == np.floor(ints)) and ints.max() < 2**32
    return ints.astype(np.uint64)


def write_sobol() -> None:
    import warnings
    warnings.simplefilter("ignore")  # SciPy warns about unscrambled Sobol'
    # d = 64, 2^16 points: a digest per dimension, and the first 64 points in full.
    x = sobol_u32(64, 1 << 16)
    with (HERE / "scipy_sobol_d64_n65536.txt").open("w") as f:
        f.write(f"# scipy {scipy.__version__}: qmc.Sobol(64, scramble=False, bits=32)"
                ".random(65536) * 2^32, Gray order\n")
        f.write("# digest dim fnv1a64(le u32 bytes of the 65536 values of that dimension)\n")
        for dim in range(64):
            f.write(f"digest {dim} {fnv1a64(x[:, dim]):016x}\n")
        f.write("# point index v_0 .. v_63 for the first 64 points\n")
        for i in range(64):
            f.write(f"point {i} " + " ".join(str(int(v)) for v in x[i]) + "\n")
    # d = 21201, 1024 points: a digest per block of 100 dimensions, and spot dimensions.
    n, d = 1024, 21201
    x = sobol_u32(d, n)
    with (HERE / "scipy_sobol_d21201_n1024.txt").open("w") as f:
        f.write(f"# scipy {scipy.__version__}: qmc.Sobol(21201, scramble=False, bits=32)"
                ".random(1024) * 2^32, Gray order\n")
        f.write("# block first_dim end_dim fnv1a64(le u32 bytes, point-major over the block)\n")
        for lo in range(0, d, 100):
            hi = min(d, lo + 100)
            f.write(f"block {lo} {hi} {fnv1a64(x[:, lo:hi].reshape(-1)):016x}\n")
        f.write("# column dim v_0 .. v_1023 (0-based dimension)\n")
        for dim in (64, 99, 1023, 1024, 4999, 9999, 14999, 21199, 21200):
            f.write(f"column {dim} " + " ".join(str(int(v)) for v in x[:, dim]) + "\n")


if __name__ == "__main__":
    write_halton(64, 64)
    write_halton(8, 512)
    write_halton(2, 2048)
    write_radical_inverses()
    write_sobol()
