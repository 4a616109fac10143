#!/usr/bin/env python3
"""The tables of docs/spectra.md, from the `qmckit` command alone.

Run: `cargo build --release -p qmckit-cli && python3 scripts/spectra_docs.py [SAMPLER..]`
from the repository root (numpy for the slope fits; the optional names restrict the rows).
Prints markdown.

1. Mean radial periodograms of 100 sets of N = 1024 points (K = 64) of white noise,
   jittered, Halton, Sobol', Owen-scrambled Sobol', Poisson disk (about N points on the
   torus) and Gaussian blue noise (`qmckit spectrum --average --radial`). Halton's and
   Sobol's 100 sets are the consecutive blocks of 1024 points (`--start`).
2. `qmckit variance` for N = 16 ... 4096, disk R = 1/4 and Gaussian sigma = 0.1, with the
   least-squares slopes of log Var against log N. Gaussian blue noise costs O(N) a point
   and iteration (500 iterations), so it runs fewer sets at large N (SETS_GBN).
"""
import subprocess
import sys

import numpy as np

Q = "./target/release/qmckit"
N, K, SETS = 1024, 64, 100


def run(args, stdin=None):
    return subprocess.run([Q, *args], input=stdin, capture_output=True, text=True, check=True).stdout


def points(sampler, s):
    if sampler == "white":
        return run(["points", "independent", "-n", str(N), "--seed", str(s)])
    if sampler == "jittered":
        return run(["points", "stratified", "-n", str(N), "--seed", str(s)])
    if sampler in ("halton", "sobol"):
        return run(["points", sampler, "-n", str(N), "--start", str(s * N)])
    if sampler == "poisson":
        return run(["points", "poisson", "-n", str(N), "--torus", "--seed", str(s)])
    if sampler == "gaussian-blue-noise":
        return run(["points", "gaussian-blue-noise", "-n", str(N), "--seed", str(s), "--max-seconds", "600"])
    return run(["points", "sobol", "-n", str(N), "--scramble", "owen", "--seed", str(s)])


SAMPLERS = ["white", "jittered", "halton", "sobol", "owen-sobol", "poisson", "gaussian-blue-noise"]
SETS_GBN = {16: "200", 64: "200", 256: "100", 1024: "30", 4096: "10"}
# Optional: the samplers to run (names of either table), e.g. `poisson gaussian-blue-noise`.
ONLY = set(sys.argv[1:])
at = [4, 8, 16, 24, 32, 48, 64]
print(f"| sampler ({SETS} sets, N = {N}) | mean P, |k| < 0.5 sqrt(N) | " + " | ".join(f"r = {r} ({r / 32:.3g} sqrt N)" for r in at) + " |")
print("|---|---|" + "---|" * len(at))
for name in SAMPLERS:
    if ONLY and name not in ONLY:
        continue
    text = "#\n".join(points(name, s) for s in range(SETS))
    out = run(["spectrum", "--average", "--radial", "--k-max", str(K)], text)
    rows = [l.split() for l in out.splitlines() if not l.startswith("#")]
    radial = {int(r[0]): (int(r[1]), float(r[2])) for r in rows}
    low = [radial[r] for r in range(1, 16)]
    low_mean = sum(c * m for c, m in low) / sum(c for c, _ in low)
    print(f"| {name} | {low_mean:.4f} | " + " | ".join(f"{radial[r][1]:.3f}" for r in at) + " |", flush=True)

print()
ns = [16, 64, 256, 1024, 4096]
for integrand in ["disk", "gaussian"]:
    print(f"| sampler ({integrand}) | " + " | ".join(f"N = {n}: predicted / measured" for n in ns) + " | slope predicted | slope measured |")
    print("|---|" + "---|" * len(ns) + "---|---|")
    for sampler in ["independent", "jittered", "halton", "sobol", "owen-sobol", "poisson", "gaussian-blue-noise"]:
        if ONLY and sampler not in ONLY:
            continue
        pred, meas, cells = [], [], []
        for n in ns:
            sets = "1000" if n <= 1024 else "300"
            if sampler == "gaussian-blue-noise":
                sets = SETS_GBN[n]
            out = run(["variance", sampler, "-n", str(n), "--integrand", integrand, "--sets", sets, "--max-seconds", "3000"])
            kv = dict(l.split(" ", 1) for l in out.splitlines())
            p, m = float(kv["predicted"]), float(kv["measured"])
            pred.append(p)
            meas.append(m)
            cells.append(f"{p:.3e} / {m:.3e}")
        sp = np.polyfit(np.log(ns), np.log(pred), 1)[0]
        sm = np.polyfit(np.log(ns), np.log(meas), 1)[0]
        print(f"| {sampler} | " + " | ".join(cells) + f" | {sp:.2f} | {sm:.2f} |", flush=True)
    print()
