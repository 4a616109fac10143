"""Golden points of a Niederreiter-Xing net read from an LDData generator-matrix file.

`mps.nx_b2_m30_s4_Cs.txt` (LDData `dnet/`, from the Magic Point Shop) holds 4 generator
matrices of 30 columns, each column an integer whose 30 bits are its rows. QMCPy's
`DigitalNetB2` reads these files with the most significant bit as row 0 (`msb=True`,
`t` = the header's bit count); this script gives QMCPy the same integers in that reading
and writes the first 1024 points in natural order, unrandomized, as 30-bit integers
(`x * 2^30`), one point per line: `mps_nx_s4_qmcpy.txt`.

    pip install qmcpy==2.4
    python3 tests/golden/gen_qmcpy_dnet.py
"""
import os

import numpy as np
import qmcpy

HERE = os.path.dirname(os.path.abspath(__file__))
lines = [l.split("#", 1)[0].strip() for l in open(os.path.join(HERE, "mps.nx_b2_m30_s4_Cs.txt"))]
lines = [l for l in lines if l]
base, dims, npts, bits = (int(v) for v in lines[:4])
assert (base, dims, npts, bits) == (2, 4, 2**30, 30)
mats = np.array([[int(v) for v in l.split()] for l in lines[4 : 4 + dims]], dtype=np.uint64)
net = qmcpy.DigitalNetB2(
    dims, randomize=False, generating_matrices=mats, msb=True, t=30, order="NATURAL"
)
x = net.gen_samples(1024, warn=False)
ints = np.rint(x * 2.0**30).astype(np.int64)
assert np.all(ints / 2.0**30 == x)
with open(os.path.join(HERE, "mps_nx_s4_qmcpy.txt"), "w") as f:
    f.write("# qmcpy %s DigitalNetB2(msb=True, t=30, NATURAL), x * 2^30\n" % qmcpy.__version__)
    for row in ints:
        f.write(" ".join(str(v) for v in row) + "\n")
