"""Points QMCPy's CubQMCSobolG (QMCPy 2.4) uses to reach an absolute tolerance on three of
qmckit's test problems (the same integrands and parameters as
qmckit::analysis::integrate::test_suite), written to tests/golden/qmcpy_cubqmc_points.txt
for the comparison printed by the integrate test `points_used_against_qmcpy`.

Run from the repository root: python3 tests/golden/compare_qmcpy_cubqmc.py
"""
import math
import pathlib
import warnings

import numpy as np
import qmcpy
from scipy import special, stats

warnings.filterwarnings("ignore")


def gaussian_d5(x):
    d = 5
    a = np.array([3.0 * (1 + k) / d for k in range(d)])
    u = np.array([0.2 + 0.6 * math.modf(k * 0.618)[0] for k in range(d)])
    return np.exp(-np.sum(a**2 * (x - u) ** 2, axis=-1))


def keister_d3(x):
    z = stats.norm.ppf(x) / np.sqrt(2)
    return np.pi ** 1.5 * np.cos(np.sqrt(np.sum(z**2, axis=-1)))


def european_d4(x):
    # Only W_T matters: the Brownian bridge's first coordinate.
    w = stats.norm.ppf(x[..., 0])
    s = 100 * np.exp((0.05 - 0.02) + 0.2 * w)
    return np.exp(-0.05) * np.maximum(s - 100, 0)


rows = []
for name, d, f, tol in [("genz-gaussian-d5", 5, gaussian_d5, 1e-4),
                        ("keister-d3", 3, keister_d3, 1e-3),
                        ("european-d4", 4, european_d4, 1e-2)]:
    used = []
    for seed in range(10):
        integrand = qmcpy.CustomFun(qmcpy.Uniform(qmcpy.DigitalNetB2(d, seed=seed)), g=f)
        sol, data = qmcpy.CubQMCSobolG(integrand, abs_tol=tol).integrate()
        used.append(int(data.n_total))
    rows.append(f"{name} {tol!r} {int(np.median(used))}")
lines = ["# name abs_tol median-points-of-CubQMCSobolG-over-10-seeds"] + rows
pathlib.Path("tests/golden/qmcpy_cubqmc_points.txt").write_text("\n".join(lines) + "\n")
print("\n".join(lines))
