#!/usr/bin/env python3
"""Regenerate the golden files in this folder from oracles qmckit did not write.

  * SciPy's `scipy.stats.qmc.Halton(d, scramble=False)` (float64; starts at index 0).
  * Exact radical inverses from Python's `fractions.Fraction`, straight from the
    definition phi_b(i) = sum_j d_j b^-j.

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


if __name__ == "__main__":
    write_halton(64, 64)
    write_halton(8, 512)
    write_halton(2, 2048)
    write_radical_inverses()
