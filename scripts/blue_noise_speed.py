"""Poisson-disk and void-and-cluster timings side by side: SciPy's qmc.PoissonDisk (pure
Python loop), the fast_poisson crate and qmckit (both from examples/blue_noise_speed.rs),
and the blue-noise crate for masks. Prints one table with time per point and the ratios.

    pip install scipy numpy
    python3 scripts/blue_noise_speed.py [--scipy-radius 0.02] [--radius 0.00078] [--side 256]
"""
import argparse
import subprocess
import time

import numpy as np
from scipy.stats import qmc


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--scipy-radius", type=float, default=0.02)
    ap.add_argument("--radius", type=float, default=0.00078)
    ap.add_argument("--side", type=int, default=256)
    a = ap.parse_args()
    rows = []
    for seed in (1, 2):
        eng = qmc.PoissonDisk(d=2, radius=a.scipy_radius, rng=np.random.default_rng(seed))
        t = time.perf_counter()
        pts = eng.fill_space()
        s = time.perf_counter() - t
        n = len(pts)
        rows.append(("scipy", f"poisson_r{a.scipy_radius}", n, n * a.scipy_radius**2, s, s / n * 1e9))
    for radius, side in ((a.scipy_radius, 64), (a.radius, a.side)):
        out = subprocess.run(
            ["cargo", "run", "-q", "--release", "--features", "analysis", "--example",
             "blue_noise_speed", "--",
             str(radius), str(side)],
            check=True, capture_output=True, text=True).stdout
        for line in out.splitlines():
            f = line.split()
            rows.append((f[0], f[1], int(f[2]), float(f[3]), float(f[4]), float(f[5])))
    print(f"{'impl':14} {'task':26} {'points':>8} {'N r^2':>7} {'seconds':>9} {'ns/point':>11}")
    for r in rows:
        print(f"{r[0]:14} {r[1]:26} {r[2]:8d} {r[3]:7.4f} {r[4]:9.4f} {r[5]:11.1f}")
    def best(impl, task):
        v = [r[5] for r in rows if r[0] == impl and r[1] == task]
        return min(v) if v else None
    small = f"poisson_r{a.scipy_radius}"
    big = f"poisson_r{a.radius}"
    q_small, s_small = best("qmckit", small), best("scipy", small)
    q_big, f_big = best("qmckit", big), best("fast_poisson", big)
    q45 = best("qmckit_k45", big)
    print(f"scipy / qmckit per point (r={a.scipy_radius}): {s_small / q_small:.0f}x")
    print(f"fast_poisson / qmckit per point (r={a.radius}): {f_big / q_big:.2f}x")
    dens = {r[0]: r[3] for r in rows if r[1] == big}
    print(f"fast_poisson / qmckit k=45 per point (r={a.radius}, density {dens.get('qmckit_k45', 0):.4f}"
          f" vs {dens.get('fast_poisson', 0):.4f}): {f_big / q45:.2f}x")
    v = best("blue-noise", "void_and_cluster_64x64")
    q = best("qmckit", "void_and_cluster_64x64")
    if v and q:
        print(f"blue-noise / qmckit, 64x64 mask: {v / q:.1f}x")


if __name__ == "__main__":
    main()
