#!/bin/sh
# The pictures of docs/blue-noise.md, "The workbench samplers: pictures": points of each
# sampler at 1024 points in 2D, the mean radial spectra and pair correlations of 8 sets,
# and the mean radial spectra of the 2D projection (axes 1 and 2) of 3D sets.
# Usage: scripts/sampler_figures.sh [QMCKIT] (default: target/release/qmckit), run from
# the repository root; writes docs/figures/.
set -eu
Q=${1:-target/release/qmckit}
OUT=docs/figures
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

# NAME LABEL [OPTIONS...]: 8 sets (hex: 1) of 1024 points, separated by '#' lines.
sets() {
    name=$1
    shift
    if [ "$name" = hex ]; then
        "$Q" points hex -n 1024 --total 1024
        return
    fi
    for k in 0 1 2 3 4 5 6 7; do
        "$Q" points "$name" -n 1024 --seed "$k" "$@"
        echo '#'
    done | sed '$d'
}

: >"$TMP/radial"
: >"$TMP/pcf"
for spec in "cmj cmj" "hex hex" "lloyd lloyd" "ccvt ccvt" "sot sot" \
    "sot sot-projective --projective" "projective-blue-noise projective-blue-noise" \
    "forced-random forced-random" "penrose penrose"; do
    # shellcheck disable=SC2086
    set -- $spec
    name=$1
    label=$2
    shift 2
    sets "$name" "$@" >"$TMP/sets"
    sed -n '1,/^#/p' "$TMP/sets" | grep -v '^#' >"$TMP/first"
    "$Q" plot --out "$OUT/sampler-$label-points.png" --size 420x420 "$TMP/first"
    { echo '#'; echo "# label: $label"; "$Q" spectrum --average --radial --k-max 96 <"$TMP/sets" | grep -v '^#'; } >>"$TMP/radial"
    { echo '#'; echo "# label: $label"; "$Q" pcf --average <"$TMP/sets" | grep -v '^#'; } >>"$TMP/pcf"
done
sed '1d' "$TMP/radial" | "$Q" plot --kind radial --out "$OUT/samplers-radial-spectra.png" \
    --title "mean radial power spectrum, 1024 points (8 sets; hex: 1)"
sed '1d' "$TMP/pcf" | "$Q" plot --kind pcf --out "$OUT/samplers-pcf.png" \
    --title "pair correlation, 1024 points (8 sets; hex: 1)"

# The 2D projection (coordinates 1 and 2) of 3D sets: plain against projective.
: >"$TMP/proj"
for spec in "independent independent" "poisson poisson-3d" "sot sot" \
    "sot sot-projective --projective" "projective-blue-noise projective-blue-noise"; do
    # shellcheck disable=SC2086
    set -- $spec
    name=$1
    label=$2
    shift 2
    if [ "$name" = poisson ]; then extra=--torus; else extra=; fi
    for k in 0 1 2 3 4 5 6 7; do
        # shellcheck disable=SC2086
        "$Q" points "$name" -n 1024 -d 3 --seed "$k" $extra "$@" | cut -d' ' -f1,2
        echo '#'
    done | sed '$d' >"$TMP/sets"
    if [ "$name" = projective-blue-noise ]; then
        sed -n '1,/^#/p' "$TMP/sets" | grep -v '^#' >"$TMP/first"
        "$Q" plot --out "$OUT/sampler-projective-3d-xy.png" --size 420x420 "$TMP/first"
    fi
    { echo '#'; echo "# label: $label"; "$Q" spectrum --average --radial --k-max 96 <"$TMP/sets" | grep -v '^#'; } >>"$TMP/proj"
done
sed '1d' "$TMP/proj" | "$Q" plot --kind radial --out "$OUT/samplers-projection-spectra.png" \
    --title "mean radial spectrum of the (x, y) projection of 3D sets, 1024 points (8 sets)"
