#!/usr/bin/env python3
"""Golden files for qmckit::analysis::l2 from SciPy's `qmc.discrepancy`.

Run: `pip install scipy==1.17.1 && python3 tests/golden/gen_discrepancy.py` (from anywhere).
Deterministic (unscrambled Sobol', numpy `default_rng` with fixed seeds, fixed grids);
writes tests/golden/scipy_discrepancy_<name>.txt, read by tests/golden_discrepancy.rs
(`cargo test` never runs Python).

Each file holds the point set (float repr, one point per line) and, for the four SciPy
methods (L2-star with the square root taken; CD, WD, MD squared), two values:

  * `scipy`: `qmc.discrepancy(points, method=m)` as returned (plain double sums);
  * `ref`:   the same formula with every kernel product computed in float64 (numpy), the
    sums taken exactly (`math.fsum`) and the three terms combined exactly
    (`fractions.Fraction`), then rounded once: the formula's value on these points to about
    1e-15 relative, independent of summation order.

The two differ when the terms cancel (good sets: a WD^2 of 1e-3 built from terms near 10),
because SciPy's plain sums carry errors of about n * eps * (largest term); the script
prints the difference and the Rust test uses a tolerance scaled by that cancellation.
"""
import math
import warnings
from fractions import Fraction
from pathlib import Path

import numpy as np
import scipy
from scipy.stats import qmc

HERE = Path(__file__).resolve().parent
METHODS = ["L2-star", "CD", "WD", "MD"]


def sobol(d, n):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # n not a power of two
        return qmc.Sobol(d, scramble=False).random(n)


def uniform(d, n, seed):
    return np.random.default_rng(seed).random((n, d))


def grid_with_edges():
    """7 points in 3D with coordinates in {0, 1/4, 1/2, 1}: corners 0 and 1 included."""
    rng = np.random.default_rng(7)
    pts = rng.choice([0.0, 0.25, 0.5, 1.0], size=(7, 3))
    pts[0] = [0.0, 0.0, 0.0]
    pts[1] = [1.0, 1.0, 1.0]
    pts[2] = [0.0, 1.0, 0.5]
    return pts


SETS = {
    "sobol_d2_n64": lambda: sobol(2, 64),
    "sobol_d2_n1024": lambda: sobol(2, 1024),
    "sobol_d5_n256": lambda: sobol(5, 256),
    "sobol_d8_n256": lambda: sobol(8, 256),
    "sobol_d3_n1000": lambda: sobol(3, 1000),
    "uniform_d1_n7": lambda: uniform(1, 7, 1),
    "uniform_d2_n1000": lambda: uniform(2, 1000, 2),
    "uniform_d5_n1": lambda: uniform(5, 1, 3),
    "uniform_d8_n64": lambda: uniform(8, 64, 4),
    "edges_d3_n7": grid_with_edges,
}


def kernel_terms(x, method):
    """(constant, coefficient a, g products, coefficient b, pair products) such that
    D^2 = constant - a/n sum g + b/n^2 sum pairs."""
    n, d = x.shape
    a_ = np.abs(x - 0.5)
    diff = np.abs(x[:, None, :] - x[None, :, :])
    if method == "L2-star":
        g = np.prod(1 - x**2, axis=1)
        k = np.prod(1 - np.maximum(x[:, None, :], x[None, :, :]), axis=2)
        return Fraction(1, 3**d), Fraction(2) ** (1 - d), g, 1, k
    if method == "CD":
        g = np.prod(1 + 0.5 * a_ - 0.5 * a_**2, axis=1)
        k = np.prod(1 + 0.5 * a_[:, None, :] + 0.5 * a_[None, :, :] - 0.5 * diff, axis=2)
        return Fraction(13, 12) ** d, 2, g, 1, k
    if method == "WD":
        k = np.prod(1.5 - diff * (1 - diff), axis=2)
        return -Fraction(4, 3) ** d, 0, np.zeros(n), 1, k
    if method == "MD":
        g = np.prod(5 / 3 - 0.25 * a_ - 0.25 * a_**2, axis=1)
        k = np.prod(15 / 8 - 0.25 * a_[:, None, :] - 0.25 * a_[None, :, :]
                    - 0.75 * diff + 0.5 * diff**2, axis=2)
        return Fraction(19, 12) ** d, 2, g, 1, k
    raise ValueError(method)


def exact_sum(values):
    """The sum of float64 values as a Fraction, to about 2^-106 relative: math.fsum rounds
    the exact sum once; the fsum of the values minus that rounded sum is the residual."""
    values = list(values)
    head = math.fsum(values)
    tail = math.fsum(values + [-head])
    return Fraction(head) + Fraction(tail)


def reference(x, method):
    n = x.shape[0]
    c, a, g, b, k = kernel_terms(x, method)
    s1 = exact_sum(g.ravel().tolist())
    s2 = exact_sum(k.ravel().tolist())
    sq = c - Fraction(a) * s1 / n + Fraction(b) * s2 / (n * n)
    if method == "L2-star":
        return math.sqrt(max(float(sq), 0.0))
    return float(sq)


def write(name, x):
    n, d = x.shape
    path = HERE / f"scipy_discrepancy_{name}.txt"
    lines = [
        f"# scipy {scipy.__version__} numpy {np.__version__}: qmc.discrepancy(points, method=m)",
        "# metric scipy_value reference_value (see gen_discrepancy.py); then the points",
        f"n {n}",
        f"d {d}",
    ]
    worst = 0.0
    for m in METHODS:
        s = float(qmc.discrepancy(x, method=m))
        r = reference(x, m)
        rel = abs(s - r) / abs(r) if r != 0 else abs(s)
        worst = max(worst, rel)
        lines.append(f"{m} {s!r} {r!r}")
    lines.append("points")
    lines += [" ".join(repr(float(v)) for v in row) for row in x]
    path.write_text("\n".join(lines) + "\n")
    print(f"{path.name}: n={n} d={d} worst |scipy-ref|/ref = {worst:.2e}")


def main():
    for name, make in SETS.items():
        write(name, np.ascontiguousarray(make(), dtype=np.float64))


if __name__ == "__main__":
    main()
