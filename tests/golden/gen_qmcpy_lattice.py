"""Golden files for qmckit's lattice, Kronecker and Faure tests, from QMCPy (pip install
qmcpy; made with QMCPy 2.4, numpy 2.4) and exact arithmetic (Python integers, decimal).

Run from the repository root: python3 tests/golden/gen_qmcpy_lattice.py
Every file: '#' comment lines, then one point a line.
  qmcpy_lattice_*.txt   coordinates times 2^32 (exact: the points are dyadic)
  qmcpy_kronecker_*.txt coordinates times 2^32 (exact: alpha and the shift are 32-bit dyadic)
  qmcpy_faure_*.txt     coordinates as QMCPy's float64 (repr)
  rd_alpha.txt          lines 'd j floor(phi_d^-j 2^32)' from 60-digit decimal arithmetic
"""
import decimal
import pathlib
import warnings

import numpy as np
import qmcpy

warnings.filterwarnings("ignore")
OUT = pathlib.Path("tests/golden")
TWO32 = 2**32


def write(name, header, rows, fmt):
    lines = [f"# {h}" for h in header]
    lines += [" ".join(fmt(v) for v in row) for row in rows]
    (OUT / name).write_text("\n".join(lines) + "\n")


def as_u32(x):
    y = x * TWO32
    assert np.all(y == np.floor(y)), "not a 32-bit dyadic point"
    return y.astype(np.uint64)


# Lattice, QMCPy's default vector (Kuo's lattice-33002-1024-1048576.9125), radical-inverse order.
lat = qmcpy.Lattice(8, randomize=False, order="RADICAL INVERSE")
write("qmcpy_lattice_natural_d8_n1024.txt",
      ["qmcpy.Lattice(8, randomize=False, order='RADICAL INVERSE')(1024) * 2^32"],
      as_u32(lat(1024)), str)
# Linear order: frac(i z / n), n = 256.
lin = qmcpy.Lattice(8, randomize=False, order="LINEAR")
write("qmcpy_lattice_linear_d8_n256.txt",
      ["qmcpy.Lattice(8, randomize=False, order='LINEAR')(256) * 2^32"],
      as_u32(lin(256)), str)
# A random shift, replaced by a 32-bit dyadic one so the sums are exact in float64.
rng = np.random.default_rng(19)
shift = rng.integers(0, TWO32, size=4, dtype=np.uint64)
sh = qmcpy.Lattice(4, randomize="SHIFT", order="RADICAL INVERSE", seed=7)
sh.shift = (shift.astype(np.float64) / TWO32)[None, :]
write("qmcpy_lattice_shifted_d4_n64.txt",
      ["qmcpy.Lattice(4, randomize='SHIFT') with .shift = first data line / 2^32, (64) * 2^32",
       "first data line: the shift times 2^32"],
      [shift] + list(as_u32(sh(64))), str)

# Kronecker with 32-bit dyadic alpha and shift (QMCPy: (i alpha + shift) mod 1).
alpha = np.array([0xC13FA9A9, 0x91E10DA5, 0x6A09E667], dtype=np.uint64)
kshift = np.array([0x80000000, 0x12345678, 0xFEDCBA98], dtype=np.uint64)
kr = qmcpy.Kronecker(3, generating_vector=alpha.astype(np.float64) / TWO32,
                     shift=kshift.astype(np.float64) / TWO32)
write("qmcpy_kronecker_d3_n256.txt",
      ["qmcpy.Kronecker(3, generating_vector=a/2^32, shift=s/2^32)(256) * 2^32",
       "first data line: a; second: s"],
      [alpha, kshift] + list(as_u32(kr(256))), str)

# Faure in base 3 (d = 3) and base 5 (d = 5), unrandomized.
for d, n in [(3, 243), (5, 625)]:
    f = qmcpy.Faure(d, randomize=False)
    write(f"qmcpy_faure_d{d}_n{n}.txt", [f"qmcpy.Faure({d}, randomize=False)({n})"],
          f(n), lambda v: repr(float(v)))

# R_d: phi_d is the root > 1 of x^(d+1) = x + 1; alpha_j = phi_d^-j.
decimal.getcontext().prec = 60
rows = []
for d in [1, 2, 3, 4, 5, 8, 16, 100, 1000]:
    lo, hi = decimal.Decimal(1), decimal.Decimal(2)
    for _ in range(200):
        mid = (lo + hi) / 2
        if mid ** (d + 1) - mid - 1 > 0:
            hi = mid
        else:
            lo = mid
    for j in sorted({1, min(2, d), d // 2 + 1, d}):
        rows.append((d, j, int((lo ** -j) * TWO32)))
write("rd_alpha.txt", ["d j floor(phi_d^-j 2^32), 60-digit decimal bisection"], rows, str)
