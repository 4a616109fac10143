#!/bin/sh
# The spectral samplers' pictures of docs/blue-noise.md: points of step, single-peak and
# kernel-density blue noise at 1024 points, and the mean radial spectra and pair
# correlations of 4 sets each, drawn with the targets. The targets are computed here, not
# by the library: the step P(u) = H(u - u_s), u_s = 0.9995 / sqrt(pi) = 0.5639 (just inside
# the realizability bound V_2^(-1/2)), and the single peak
# P(u) = p0 phi((u - u0) / s) / s + Phi((u - u0) / s) (u0 = 0.75, p0 = 0.3, s = 0.08),
# u = |k| / sqrt(N); their pair correlations by the 2D Hankel transform
# g(r) = 1 + (1 / N) int_0^inf (P(k / sqrt N) - 1) J0(2 pi k r) 2 pi k dk (SciPy's Bessel
# function and quadrature).
# Usage: scripts/spectral_figures.sh [QMCKIT] [PYTHON] (defaults: target/release/qmckit,
# python3 with numpy and scipy), run from the repository root; writes docs/figures/.
set -eu
Q=${1:-target/release/qmckit}
PY=${2:-python3}
OUT=docs/figures
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
N=1024

: >"$TMP/radial"
: >"$TMP/pcf"
for name in step-blue-noise single-peak-blue-noise kde-blue-noise; do
    for k in 0 1 2 3; do
        "$Q" points "$name" -n "$N" --seed "$k" --max-seconds 100
        echo '#'
    done | sed '$d' >"$TMP/sets"
    sed -n '1,/^#/p' "$TMP/sets" | grep -v '^#' >"$TMP/first"
    "$Q" plot --out "$OUT/sampler-$name-points.png" --size 420x420 "$TMP/first"
    { echo '#'; echo "# label: $name"; "$Q" spectrum --average --radial --k-max 96 <"$TMP/sets" | grep -v '^#'; } >>"$TMP/radial"
    { echo '#'; echo "# label: $name"; "$Q" pcf --torus --average <"$TMP/sets" | grep -v '^#'; } >>"$TMP/pcf"
done

"$PY" - "$N" "$TMP" <<'PYEOF'
import sys
import numpy as np
from scipy import integrate, special, stats

n = int(sys.argv[1])
tmp = sys.argv[2]
root = np.sqrt(n)
u0, p0, s = 0.75, 0.3, 0.08
us = 0.9995 / np.sqrt(np.pi)

def step(u):
    return np.where(u < us, 0.0, 1.0)

def peak(u):
    return p0 * stats.norm.pdf((u - u0) / s) / s + stats.norm.cdf((u - u0) / s)

with open(f"{tmp}/radial", "a") as f:
    for label, p in (("step target", step), ("single-peak target", peak)):
        f.write(f"#\n# label: {label}\n")
        for k in range(1, 97):
            f.write(f"{k} 1 {float(p(k / root))!r} 0\n")

# Pair correlations. Step: closed form, g(r) = 1 - K J1(2 pi K r) / (N r), K = u_s sqrt N.
# Single peak: the transform of P - 1, which decays like a Gaussian past the peak.
rs = np.linspace(3.75e-4, 0.15, 200)
kk = us * root
with open(f"{tmp}/pcf", "a") as f:
    f.write("#\n# label: step target\n")
    for r in rs:
        f.write(f"{float(r)!r} {float(1 - kk * special.j1(2 * np.pi * kk * r) / (n * r))!r}\n")
    f.write("#\n# label: single-peak target\n")
    top = root * (u0 + 12 * s)
    for r in rs:
        val, _ = integrate.quad(
            lambda k: (peak(k / root) - 1) * special.j0(2 * np.pi * k * r) * 2 * np.pi * k,
            0, top, limit=400)
        f.write(f"{float(r)!r} {float(1 + val / n)!r}\n")
PYEOF

sed '1d' "$TMP/radial" | "$Q" plot --kind radial --out "$OUT/spectral-samplers-radial-spectra.png" \
    --title "mean radial power spectrum, 1024 points (4 sets), and the targets"
sed '1d' "$TMP/pcf" | "$Q" plot --kind pcf --out "$OUT/spectral-samplers-pcf.png" \
    --title "pair correlation on the torus, 1024 points (4 sets), and the targets"
