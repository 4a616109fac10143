"""Speed per value of qmckit's lattice, Kronecker and Sobol' generators against QMCPy's
Lattice and Kronecker and SciPy's Sobol', side by side in one run.

qmckit is timed twice: as the library (`cargo bench --bench toolbox`: `fill_as::<f64>`
into an array, the same work as the peers' calls) and as the command
`qmckit points ... --format npy > /dev/null` (generation, conversion and writing the .npy
stream; process start included, so N is large). The peers are the Python calls that
return the float64 array. Best of 5 runs each, all in one run of this script.

  cargo build --release -p qmckit-cli
  pip install qmcpy scipy
  python3 benches/peers_python.py [path/to/qmckit]
"""
import subprocess
import sys
import time
import warnings

import numpy as np
import qmcpy
from scipy.stats import qmc

warnings.filterwarnings("ignore")
QMCKIT = sys.argv[1] if len(sys.argv) > 1 else "target/release/qmckit"
M, D = 20, 8
N = 2**M
REPEAT = 5


def best(fn):
    times = []
    for _ in range(REPEAT):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


def cli(*args):
    cmd = [QMCKIT, "points", *args, "-n", str(N), "-d", str(D), "--format", "npy"]
    return lambda: subprocess.run(cmd, stdout=subprocess.DEVNULL, check=True)


bench = subprocess.run(["cargo", "bench", "--bench", "toolbox"], capture_output=True,
                       text=True, check=True).stdout
lib = {name: float(ns) for name, ns in (l.split() for l in bench.splitlines() if l.strip())}
LIB = {"lattice + random shift": "lattice-shift", "kronecker + random shift": "kronecker-shift",
       "sobol + LMS and shift": "sobol-lms-shift", "sobol, unscrambled": "sobol"}

cases = [
    ("lattice + random shift", cli("lattice", "--scramble", "shift", "--seed", "7"),
     "qmcpy.Lattice", lambda: qmcpy.Lattice(D, seed=7)(N)),
    ("kronecker + random shift", cli("kronecker", "--scramble", "shift", "--seed", "7"),
     "qmcpy.Kronecker", lambda: qmcpy.Kronecker(D, seed=7)(N)),
    ("sobol + LMS and shift", cli("sobol", "--scramble", "lms", "--seed", "7"),
     "scipy Sobol (scrambled)", lambda: qmc.Sobol(D, scramble=True, seed=7).random_base2(M)),
    ("sobol, unscrambled", cli("sobol"),
     "scipy Sobol (unscrambled)", lambda: qmc.Sobol(D, scramble=False).random_base2(M)),
]
print(f"N = 2^{M} points, d = {D}: ns per value (best of {REPEAT})")
print(f"{'qmckit':26} {'lib ns':>7} {'cli ns':>7}   {'peer':26} {'ns':>7}   peer/lib  peer/cli")
for name, ours, peer, theirs in cases:
    a = best(ours) / (N * D) * 1e9
    b = best(theirs) / (N * D) * 1e9
    lib_ns = lib[LIB[name]]
    print(f"{name:26} {lib_ns:7.2f} {a:7.2f}   {peer:26} {b:7.2f}   {b / lib_ns:7.2f}x {b / a:7.2f}x")
print("qmckit only (library):", ", ".join(f"{k} {v:.1f} ns" for k, v in lib.items()))
