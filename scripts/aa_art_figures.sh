#!/bin/sh
# The pictures of docs/blue-noise.md, "AA patterns and ART": points of aa-patterns and art
# at 1024 points, art following a density, and the mean radial spectra and pair
# correlations of 8 sets of 1024 points beside jittered sampling (stratified) and penrose.
# Usage: scripts/aa_art_figures.sh [QMCKIT] (default: target/release/qmckit), run from the
# repository root; writes docs/figures/.
set -eu
Q=${1:-target/release/qmckit}
OUT=docs/figures
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

: >"$TMP/radial"
: >"$TMP/pcf"
for name in stratified penrose aa-patterns art; do
    for k in 0 1 2 3 4 5 6 7; do
        "$Q" points "$name" -n 1024 --seed "$k"
        echo '#'
    done | sed '$d' >"$TMP/sets"
    if [ "$name" = aa-patterns ] || [ "$name" = art ]; then
        sed -n '1,/^#/p' "$TMP/sets" | grep -v '^#' >"$TMP/first"
        "$Q" plot --out "$OUT/sampler-$name-points.png" --size 420x420 "$TMP/first"
    fi
    { echo '#'; echo "# label: $name"; "$Q" spectrum --average --radial --k-max 96 <"$TMP/sets" | grep -v '^#'; } >>"$TMP/radial"
    { echo '#'; echo "# label: $name"; "$Q" pcf --average <"$TMP/sets" | grep -v '^#'; } >>"$TMP/pcf"
done
sed '1d' "$TMP/radial" | "$Q" plot --kind radial --out "$OUT/samplers-aa-art-radial-spectra.png" \
    --title "mean radial power spectrum, 1024 points (8 sets)"
sed '1d' "$TMP/pcf" | "$Q" plot --kind pcf --out "$OUT/samplers-aa-art-pcf.png" \
    --title "pair correlation, 1024 points (8 sets)"
