"""Golden values for qmckit's integration tests (pip install scipy; made with SciPy 1.17):
the exact integrals of the 20 test problems of qmckit::analysis::integrate::test_suite,
recomputed here from their closed forms (SciPy special functions, scipy.integrate.quad for
Keister's radial integral, scipy.stats.norm for the option prices), and Student-t
quantiles from scipy.stats.t.

Run from the repository root: python3 tests/golden/gen_integrate.py
"""
import itertools
import math
import pathlib

import numpy as np
from scipy import integrate, special, stats

OUT = pathlib.Path("tests/golden")


def genz_params(d, scale):
    a = [scale * (1 + k) / d for k in range(d)]
    u = [0.2 + 0.6 * math.modf(k * 0.618)[0] for k in range(d)]
    return a, u


def genz_exact(family, a, u):
    d = len(a)
    if family == "oscillatory":
        z = np.exp(2j * np.pi * u[0])
        for ak in a:
            z *= (np.exp(1j * ak) - 1) / (1j * ak)
        return z.real
    if family == "product-peak":
        return np.prod([ak * (np.arctan(ak * (1 - uk)) + np.arctan(ak * uk)) for ak, uk in zip(a, u)])
    if family == "corner-peak":
        s = 0.0
        for v in itertools.product([0, 1], repeat=d):
            s += (-1) ** sum(v) / (1 + sum(ak * vk for ak, vk in zip(a, v)))
        return s / (math.factorial(d) * np.prod(a))
    if family == "gaussian":
        return np.prod([np.sqrt(np.pi) / (2 * ak) * (special.erf(ak * (1 - uk)) + special.erf(ak * uk))
                        for ak, uk in zip(a, u)])
    if family == "continuous":
        return np.prod([(2 - np.exp(-ak * uk) - np.exp(-ak * (1 - uk))) / ak for ak, uk in zip(a, u)])
    if family == "discontinuous":
        return np.prod([(np.exp(ak * (uk if k < 2 else 1.0)) - 1) / ak for k, (ak, uk) in enumerate(zip(a, u))])
    raise ValueError(family)


def keister(d):
    # pi^(d/2) E cos(|Z| / sqrt 2), |Z| chi with d degrees of freedom.
    f = lambda r: np.cos(r / np.sqrt(2)) * stats.chi.pdf(r, d)
    val, _ = integrate.quad(f, 0, np.inf, limit=200, epsabs=1e-14, epsrel=1e-13)
    return np.pi ** (d / 2) * val


S0, K, R, SIG, T = 100.0, 100.0, 0.05, 0.2, 1.0


def european():
    v = SIG * np.sqrt(T)
    d1 = (np.log(S0 / K) + (R + SIG**2 / 2) * T) / v
    return S0 * stats.norm.cdf(d1) - K * np.exp(-R * T) * stats.norm.cdf(d1 - v)


def asian_geometric(d):
    t = np.arange(1, d + 1) * T / d
    cov = np.minimum.outer(t, t)
    var = SIG**2 * cov.sum() / d**2
    mu = np.log(S0) + (R - SIG**2 / 2) * t.mean()
    d2 = (mu - np.log(K)) / np.sqrt(var)
    return np.exp(-R * T) * (np.exp(mu + var / 2) * stats.norm.cdf(d2 + np.sqrt(var)) - K * stats.norm.cdf(d2))


rows = []
for family, scale in [("oscillatory", 2.0), ("product-peak", 4.0), ("corner-peak", 1.0),
                      ("gaussian", 3.0), ("continuous", 2.0), ("discontinuous", 1.0)]:
    for d in [2, 5]:
        rows.append((f"genz-{family}-d{d}", genz_exact(family, *genz_params(d, scale))))
for d in [2, 3, 5, 8]:
    rows.append((f"keister-d{d}", keister(d)))
for d in [4, 16]:
    rows.append((f"european-d{d}", european()))
    rows.append((f"asian-geometric-d{d}", asian_geometric(d)))
lines = ["# name exact-integral (SciPy, closed forms)"] + [f"{n} {float(v)!r}" for n, v in rows]
(OUT / "integrate_exact.txt").write_text("\n".join(lines) + "\n")

lines = ["# level nu t: scipy.stats.t.ppf((1 + level) / 2, nu)"]
for level in [0.9, 0.95, 0.99]:
    for nu in [1, 2, 3, 4, 7, 15, 31, 100]:
        lines.append(f"{level} {nu} {float(stats.t.ppf((1 + level) / 2, nu))!r}")
(OUT / "student_t.txt").write_text("\n".join(lines) + "\n")
