#!/usr/bin/env python3
"""Write tables/new-joe-kuo-6.21201 (Joe & Kuo's text format) from SciPy's copy.

SciPy ships Joe & Kuo's `new-joe-kuo-6.21201` direction numbers as
`scipy/stats/_sobol_direction_numbers.npz`: `poly[k]` encodes the primitive polynomial of
dimension d = k + 1 as 2a + 2^s + 1 (degree s, coefficients a), and `vinit[k, :s]` holds the
initial direction numbers m_1..m_s. Row 0 is the first dimension (van der Corput), which
Joe & Kuo's file does not list. This script decodes both into the published columns
`d s a m_i`, for d = 2..21201.

Run: `pip install scipy==1.17.1 && python3 tables/convert_scipy.py`.
"""
import os
from pathlib import Path

import numpy as np
import scipy

HERE = Path(__file__).resolve().parent


def main() -> None:
    path = os.path.join(os.path.dirname(scipy.__file__), "stats", "_sobol_direction_numbers.npz")
    data = np.load(path)
    poly, vinit = data["poly"], data["vinit"]
    assert poly.shape == (21201,) and vinit.shape == (21201, 18)
    lines = ["d       s       a       m_i"]
    for k in range(1, len(poly)):
        p = int(poly[k])
        s = p.bit_length() - 1
        a = (p - (1 << s) - 1) // 2
        assert p == 2 * a + (1 << s) + 1 and 0 <= a < (1 << (s - 1)), (k, p)
        m = [int(x) for x in vinit[k, :s]]
        assert all(x % 2 == 1 and x < (1 << (i + 1)) for i, x in enumerate(m)), (k, m)
        assert all(int(x) == 0 for x in vinit[k, s:]), k
        lines.append(f"{k + 1} {s} {a} " + " ".join(map(str, m)))
    (HERE / "new-joe-kuo-6.21201").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
