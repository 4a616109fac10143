#!/usr/bin/env bash
# The estimates of the budgeted generation commands against measured running times.
#
# The refusal message gives the estimate to 0.1 s (rounded down), so the ratios of rows
# estimated below 0.5 s are coarse; most rows are sized to estimates of 0.5 to 10 s.
# For each command: the estimate (read from the refusal at --max-seconds 0.001, which is
# instant: the estimate is checked before anything runs), the wall-clock time and the CPU
# time (user + system) of a run with --max-seconds inf, and their ratios to the estimate.
# The estimates are calibrated for an otherwise idle two-core machine; on a loaded one the
# wall-clock ratio grows with the load, and the CPU ratio (for the one-thread loops, the
# idle wall-clock time) is the one to read. Then the deadline: a run whose cost no estimate
# bounds, admitted at --max-seconds B, must end within 1.5 B.
#
# Usage: scripts/budget_table_generation.sh [path/to/qmckit]   (default target/release/qmckit)
# About four minutes on an idle two-core machine. Prints a Markdown table.
set -u
BIN=${1:-target/release/qmckit}
[ -x "$BIN" ] || { echo "no binary at $BIN (cargo build --release -p qmckit-cli)" >&2; exit 1; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

estimate() {
    "$BIN" "$@" --max-seconds 0.001 2>&1 >/dev/null |
        sed -n 's/.*estimated \([0-9.]*\) s.*/\1/p'
}

row() {
    local est wall cpu
    est=$(estimate "$@")
    /usr/bin/time -f "%e %U %S" -o "$TMP/t" "$BIN" "$@" --max-seconds inf >/dev/null 2>"$TMP/err"
    read -r wall user sys <"$TMP/t"
    cpu=$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.2f", u + s }')
    awk -v c="qmckit $*" -v e="$est" -v w="$wall" -v p="$cpu" 'BEGIN {
        if (e > 0) printf "| `%s` | %.1f | %.2f | %.2f | %.2f | %.2f |\n", c, e, w, p, w / e, p / e;
        else printf "| `%s` | %s | %.2f | %.2f | - | - |\n", c, e, w, p }'
}

deadline() {
    local budget=$1
    shift
    local start end code
    start=$(date +%s.%N)
    "$BIN" "$@" --max-seconds "$budget" >/dev/null 2>"$TMP/err"
    code=$?
    end=$(date +%s.%N)
    awk -v c="qmckit $* --max-seconds $budget" -v b="$budget" -v s="$start" -v e="$end" \
        -v x="$code" -v m="$(head -c 160 "$TMP/err")" 'BEGIN {
        t = e - s; printf "| `%s` | %.2f | %.2f | %s | %s |\n", c, t, t / b, x, m }'
}

echo "| command | estimate (s) | wall (s) | CPU (s) | wall / estimate | CPU / estimate |"
echo "|---|---|---|---|---|---|"
# Poisson disk, by count and by radius, d = 1..8, torus and cube, maximal, candidates.
row points poisson -n 1000000 -d 1
row points poisson -n 4000000 -d 1
row points poisson -d 1 --radius 0.000001 --maximal
row points poisson -n 1000000
row points poisson --radius 0.0005 --torus
row points poisson --radius 0.001 --maximal
row points poisson --radius 0.003 --candidates 1000 --torus
row points poisson -n 200000 -d 3
row points poisson -d 3 --radius 0.015 --torus
row points poisson -d 3 --radius 0.03 --candidates 300 --torus
row points poisson -n 50000 -d 4
row points poisson -d 4 --radius 0.06 --torus
row points poisson -n 10000 -d 5
row points poisson -d 5 --radius 0.15 --torus
row points poisson -n 2000 -d 6
row points poisson -d 6 --radius 0.25
row points poisson -n 300 -d 7
row points poisson -d 7 --radius 0.4 --torus
row points poisson -n 1 -d 8
row points poisson -d 8 --radius 0.6 --torus
row points poisson -d 8 --radius 0.7
# The other point sets.
row points best-candidate -n 4000
row points best-candidate -n 8000 --candidates 3
row points best-candidate -n 1000 --candidates 100
row points gaussian-blue-noise -n 10000
row points gaussian-blue-noise -n 100000 --iterations 50
row points gaussian-blue-noise -n 1000000 --iterations 5
row points pmj02bn -n 300000
row points pmj02bn -n 1000000
# Void-and-cluster masks.
row mask void-and-cluster --size 256x256
row mask void-and-cluster --size 512x512
row mask void-and-cluster --size 1024x1024
row mask void-and-cluster --size 2048x64
row mask void-and-cluster --size 128x128 --sigma 8
echo
echo "Deadline: runs admitted at --max-seconds B whose estimate is too low (no estimate"
echo "bounds a maximal fill in 7D) end within 1.5 B, with one line naming the budget."
echo
echo "| command | wall (s) | wall / B | exit | stderr |"
echo "|---|---|---|---|---|"
deadline 2 points poisson --radius 1 -d 7 --torus --maximal
deadline 2 points poisson --radius 0.8 -d 6 --maximal
deadline 10 mask void-and-cluster --size 1540x1540
