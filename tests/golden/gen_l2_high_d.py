#!/usr/bin/env python3
"""Extended-precision reference values of the eight L2 measures of qmckit::analysis::l2 in
600 to 4000 dimensions, where products of d kernel factors leave the range of float64.

Run: `pip install mpmath && python3 tests/golden/gen_l2_high_d.py` (from anywhere; a few
minutes). Writes tests/golden/l2_high_d.txt, read by tests/golden_discrepancy.rs
(`cargo test` never runs Python).

Points: `z` runs through SplitMix64 seeded with the case's seed, one output per
coordinate, row-major. Kind `uniform`: `u = (z >> 32) / 2^32` in [0, 1). Kind `center`:
`15/32 + u / 16` in [15/32, 17/32) (points near the center, where the centered discrepancy
stays representable in 4000 dimensions). Kind `cluster`: the first `d` outputs `b_k` give
a base point, then coordinate k of point i is `(b_k >> 35) / 2^29 + (z >> 56) / 2^40`
(all points within 2.4e-10 of the base in every coordinate, so that the pairs weigh as
much as the diagonal in every sum). All are exact in float64 and in mpmath, so both sides
evaluate the formulas on the same points.

Formulas (the conventions of the crate's documentation: SciPy's `qmc.discrepancy` for
L2-star, CD, WD, MD; UTK for the symmetric, unanchored and generalized L2 discrepancies
and the diaphony), with all ordered pairs (i, j), the diagonal included:

  l2-star  D   : D^2 = 3^-d - 2^(1-d)/n sum_i prod (1 - x^2) + 1/n^2 sum_ij prod (1 - max(x, y))
  cd       D^2 : (13/12)^d - 2/n sum_i prod (1 + a/2 - a^2/2)
                 + 1/n^2 sum_ij prod (1 + a/2 + b/2 - |x - y|/2),  a = |x - 1/2|, b = |y - 1/2|
  wd       D^2 : -(4/3)^d + 1/n^2 sum_ij prod (3/2 - t (1 - t)),  t = |x - y|
  md       D^2 : (19/12)^d - 2/n sum_i prod (5/3 - a/4 - a^2/4)
                 + 1/n^2 sum_ij prod (15/8 - a/4 - b/4 - 3t/4 + t^2/2)
  sl2      D   : D^2 = (4/3)^d - 2/n sum_i prod (1 + 2x - 2x^2) + 2^d/n^2 sum_ij prod (1 - t)
  ul2      D   : D^2 = 12^-d - 2^(1-d)/n sum_i prod x (1 - x)
                 + 1/n^2 sum_ij prod (min(x, y) - x y)
  gl2      D   : D^2 = (4/3)^d - 2/n sum_i prod (3 - x^2)/2 + 1/n^2 sum_ij prod (2 - max(x, y))
  diaphony F   : F^2 = (1/n^2 sum_ij prod (1 + 2 pi^2 (t^2 - t + 1/6)) - 1) / ((1 + pi^2/3)^d - 1)

Every value is computed with 160-bit mantissas (about 48 digits; the largest cancellation
here costs a few digits) and printed to 30 significant digits, or as `not-representable`
when it is nonzero and outside the normal float64 range [2^-1022, f64::MAX].
"""
from pathlib import Path

import mpmath
from mpmath import mp, mpf

mp.prec = 160
HERE = Path(__file__).resolve().parent
MASK = (1 << 64) - 1
CASES = [  # (d, n, seed, kind)
    (600, 64, 600, "uniform"),
    (1000, 32, 1000, "uniform"),
    (2000, 32, 2000, "uniform"),
    (4000, 32, 4000, "uniform"),
    (4000, 32, 4001, "center"),
    (1000, 16, 1001, "cluster"),
    (2000, 16, 2001, "cluster"),
]
NAMES = ["l2-star", "cd", "wd", "md", "sl2", "ul2", "gl2", "diaphony"]
F64_MAX = mpf(2) ** 1024 - mpf(2) ** 971
F64_MIN_NORMAL = mpf(2) ** -1022


def splitmix64(seed, count):
    s = seed & MASK
    out = []
    for _ in range(count):
        s = (s + 0x9E3779B97F4A7C15) & MASK
        z = s
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
        z ^= z >> 31
        out.append(z >> 32)
    return out


def points(d, n, seed, kind):
    if kind == "cluster":
        raw = splitmix64(seed, (n + 1) * d)
        base, rest = raw[:d], raw[d:]
        coords = [
            mpf(base[j % d] >> 3) / mpf(2) ** 29 + mpf(v >> 24) / mpf(2) ** 40
            for j, v in enumerate(rest)
        ]
    elif kind == "center":
        coords = [mpf(15) / 32 + mpf(v) / mpf(2) ** 36 for v in splitmix64(seed, n * d)]
    else:
        assert kind == "uniform"
        coords = [mpf(v) / mpf(2) ** 32 for v in splitmix64(seed, n * d)]
    return [coords[i * d:(i + 1) * d] for i in range(n)]


def measures(pts):
    n, d = len(pts), len(pts[0])
    half = mpf(1) / 2
    two_pi2 = 2 * mpmath.pi ** 2
    sixth = mpf(1) / 6
    # One-point sums: l2-star, cd, md, sl2, ul2, gl2.
    s1 = [mpf(0)] * 6
    for x in pts:
        p = [mpf(1)] * 6
        for t in x:
            a = abs(t - half)
            p[0] *= 1 - t * t
            p[1] *= 1 + a / 2 - a * a / 2
            p[2] *= mpf(5) / 3 - a / 4 - a * a / 4
            p[3] *= 1 + 2 * t - 2 * t * t
            p[4] *= t * (1 - t)
            p[5] *= (3 - t * t) / 2
        s1 = [u + v for u, v in zip(s1, p)]
    # Pair sums over all ordered pairs: l2-star, cd, wd, md, sl2, ul2, gl2, diaphony.
    s2 = [mpf(0)] * 8
    for i in range(n):
        for j in range(i, n):
            p = [mpf(1)] * 8
            for x, y in zip(pts[i], pts[j]):
                t = abs(x - y)
                hi = max(x, y)
                lo = min(x, y)
                a, b = abs(x - half), abs(y - half)
                p[0] *= 1 - hi
                p[1] *= 1 + a / 2 + b / 2 - t / 2
                p[2] *= mpf(3) / 2 - t * (1 - t)
                p[3] *= mpf(15) / 8 - a / 4 - b / 4 - 3 * t / 4 + t * t / 2
                p[4] *= 1 - t
                p[5] *= lo - x * y
                p[6] *= 2 - hi
                p[7] *= 1 + two_pi2 * (t * t - t + sixth)
            w = 1 if i == j else 2
            s2 = [u + w * v for u, v in zip(s2, p)]
    nn = mpf(n)
    d2 = mpf(2) ** d
    sq = {
        "l2-star": mpf(3) ** -d - 2 / d2 / nn * s1[0] + s2[0] / nn ** 2,
        "cd": (mpf(13) / 12) ** d - 2 / nn * s1[1] + s2[1] / nn ** 2,
        "wd": -(mpf(4) / 3) ** d + s2[2] / nn ** 2,
        "md": (mpf(19) / 12) ** d - 2 / nn * s1[2] + s2[3] / nn ** 2,
        "sl2": (mpf(4) / 3) ** d - 2 / nn * s1[3] + d2 * s2[4] / nn ** 2,
        "ul2": mpf(12) ** -d - 2 / d2 / nn * s1[4] + s2[5] / nn ** 2,
        "gl2": (mpf(4) / 3) ** d - 2 / nn * s1[5] + s2[6] / nn ** 2,
        "diaphony": (s2[7] / nn ** 2 - 1) / ((1 + mpmath.pi ** 2 / 3) ** d - 1),
    }
    rooted = {"l2-star", "sl2", "ul2", "gl2", "diaphony"}
    return {k: (mpmath.sqrt(v) if k in rooted else v) for k, v in sq.items()}


def show(v):
    if v != 0 and not (F64_MIN_NORMAL <= abs(v) <= F64_MAX):
        return "not-representable"
    return mpmath.nstr(v, 30, min_fixed=0, max_fixed=0)


def main():
    lines = [
        "# qmckit::analysis::l2 in high dimension: tests/golden/gen_l2_high_d.py (mpmath,",
        "# 160-bit mantissas). Points: SplitMix64(seed), by kind (see the script), row-major.",
        "# case d n seed kind, then one line per measure: name value (or not-representable).",
    ]
    for d, n, seed, kind in CASES:
        vals = measures(points(d, n, seed, kind))
        lines.append(f"case {d} {n} {seed} {kind}")
        for name in NAMES:
            lines.append(f"{name} {show(vals[name])}")
        print(d, n, {k: show(v) for k, v in vals.items()}, flush=True)
    (HERE / "l2_high_d.txt").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
