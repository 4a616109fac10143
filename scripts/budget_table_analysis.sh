#!/usr/bin/env bash
# Calibration table of the analysis commands' time estimates (release build).
#
# For each row: the estimate, parsed from the refusal at a tiny --max-seconds (every
# analysis command names its estimate there, "estimated X s", to the millisecond below a
# second); the least wall time of REPS runs of the same command under --max-seconds 600
# (default threads); wall / estimate (the goal: 0.5 to 2 on an idle two-core machine); and,
# unless ONE_THREAD=0, the least CPU time (user + system) of REPS runs on one thread
# (RAYON_NUM_THREADS=1) and its ratio to the estimate. The estimates are per-core rates on
# two cores, so for a computation split over threads a right estimate shows a one-thread
# CPU / estimate near 2 (near 1 for the one-thread convergence curves); that column holds
# on a machine loaded by other work, where the wall times grow with the load.
# Then one run whose estimate is low (a budget far below the real time, admitted because
# the estimate is checked against the budget and the deadline is 1.25 B): it must end with
# the one-line OutOfTime error within about 1.5 B.
#
# Usage: [REPS=3] [ONE_THREAD=0] scripts/budget_table_analysis.sh [path/to/qmckit]
# About two minutes with REPS=1 on an idle two-core machine (a minute without the
# one-thread runs), three times that with REPS=3.
set -u
B=${1:-target/release/qmckit}
REPS=${REPS:-1}
ONE_THREAD=${ONE_THREAD:-1}
[ -x "$B" ] || { echo "no binary at $B (cargo build --release --all-features)" >&2; exit 1; }
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT

pts() { # name n d [sampler]
  "$B" points "${4:-sobol}" -n "$2" -d "$3" --format csv > "$T/$1.csv"
}

estimate() { # args...: the estimate in seconds, from the refusal at --max-seconds 1e-9
  "$B" "$@" --max-seconds 1e-9 2>&1 >/dev/null | grep -o 'estimated [0-9.e+-]* s' | head -1 |
    awk '{print $2}'
}

least() { # threads field args...: the least of REPS runs of wall (field 1) or CPU (field 2)
  local threads=$1 field=$2 best="" v
  shift 2
  for _ in $(seq "$REPS"); do
    if [ "$threads" = default ]; then
      /usr/bin/time -f '%e %U %S' -o "$T/t" "$B" "$@" --max-seconds 600 >/dev/null 2>"$T/err" ||
        echo "FAIL: $(cat "$T/err")" >&2
    else
      RAYON_NUM_THREADS=$threads /usr/bin/time -f '%e %U %S' -o "$T/t" "$B" "$@" \
        --max-seconds 600 >/dev/null 2>"$T/err" || echo "FAIL: $(cat "$T/err")" >&2
    fi
    v=$(awk -v f="$field" '{ if (f == 1) print $1; else print $2 + $3 }' "$T/t")
    best=$(awk -v a="${best:-$v}" -v b="$v" 'BEGIN { print (b < a) ? b : a }')
  done
  echo "$best"
}

row() { # label args...
  local label=$1; shift
  local est wall cpu=-
  est=$(estimate "$@")
  wall=$(least default 1 "$@")
  if [ "$ONE_THREAD" != 0 ]; then cpu=$(least 1 2 "$@"); fi
  if [ -z "$est" ]; then est=0; fi
  printf "| %-40s " "$label"
  echo "$est $wall $cpu" | awk '{
    r = ($1 > 0) ? sprintf("%5.2f", $2 / $1) : "-";
    c = ($3 != "-" && $1 > 0) ? sprintf("%5.2f", $3 / $1) : "-";
    printf "| %8.3f | %7.3f | %s | %7s | %s |\n", $1, $2, r, $3, c }'
}

echo "| command | estimate (s) | wall (s) | wall / estimate | CPU, one thread (s) \
| CPU / estimate |"
echo "|---|---:|---:|---:|---:|---:|"
# Exact star discrepancy: the 2D sweep, the decomposition in 3 to 8 and 12 dimensions.
for nd in "20000 2" "8000 2" "12000 3" "20000 3" "2500 4" "4000 4" "800 5" "1100 5" \
          "300 6" "400 6" "160 7" "200 7" "90 8" "120 8" "40 12"; do
  set -- $nd
  pts "s$1_$2" "$1" "$2"
  row "discrepancy star N=$1 d=$2" discrepancy --metric star "$T/s$1_$2.csv"
done
# L2 family: pair sums in 8D (tiles for cd, rows for l2-star) and 2D (the loop compiled for
# 2D), features streamed from memory (md, 500D). (The L2-star divide and conquer is too fast
# to time through the command: reading the points takes longer.)
pts l2 30000 8
row "discrepancy cd N=30000 d=8" discrepancy --metric cd "$T/l2.csv"
row "discrepancy l2-star N=30000 d=8" discrepancy --metric l2-star "$T/l2.csv"
pts l2b 30000 2
row "discrepancy cd N=30000 d=2" discrepancy --metric cd "$T/l2b.csv"
pts l2d 1024 500
row "discrepancy md N=1024 d=500" discrepancy --metric md "$T/l2d.csv"
# Spectrum, direct sums and NUFFT.
pts sp 4096 2
row "spectrum direct N=4096 K=128" spectrum --method direct --k-max 128 "$T/sp.csv"
row "spectrum direct N=4096 K=384" spectrum --method direct --k-max 384 "$T/sp.csv"
row "spectrum nufft N=4096 K=1024" spectrum --method nufft --k-max 1024 "$T/sp.csv"
row "spectrum nufft N=4096 K=2048" spectrum --method nufft --k-max 2048 "$T/sp.csv"
# Pair correlation.
pts pc 20000 2
row "pcf N=20000" pcf "$T/pc.csv"
row "pcf N=20000 torus R=0.3" pcf --torus --r-max 0.3 "$T/pc.csv"
# Variance (sets of periodograms).
row "variance independent N=1024 S=200" variance independent -n 1024 --sets 200
row "variance owen-sobol N=4096 S=100" variance owen-sobol -n 4096 --sets 100
row "variance poisson N=1024 S=50" variance poisson -n 1024 --sets 50
# Convergence (probe-timed; blue noise by construction cost).
row "convergence halton owen m=18 seeds=4" convergence halton --scramble owen --max-m 18 --seeds 4
row "convergence gaussian-blue-noise m=11" convergence gaussian-blue-noise --max-m 11
# t-value by counting (scrambled): t = 3 (4D), t = 0 (2D), t = 6 (8D), and a rotation.
row "tvalue sobol m=16 d=4 scramble owen" tvalue sobol -m 16 -d 4 --scramble owen
row "tvalue sobol m=20 d=4 scramble owen" tvalue sobol -m 20 -d 4 --scramble owen
row "tvalue sobol m=21 d=2 scramble owen" tvalue sobol -m 21 -d 2 --scramble owen
row "tvalue sobol m=14 d=8 scramble owen" tvalue sobol -m 14 -d 8 --scramble owen
row "tvalue sobol m=20 d=4 scramble rotate" tvalue sobol -m 20 -d 4 --scramble rotate

echo
echo "A run whose estimate is low: ten sets of 20000 2D points, each exact star discrepancy"
echo "estimated within the budget on its own (the estimate is per measure), the ten far"
echo "past it; the deadline (1.25 B from the start of the command) stops the run:"
pts one 20000 2
: > "$T/ten.csv"
for k in 1 2 3 4 5 6 7 8 9 10; do
  if [ "$k" -gt 1 ]; then echo "#" >> "$T/ten.csv"; fi
  cat "$T/one.csv" >> "$T/ten.csv"
done
for b in 1 4; do
  s=$(date +%s.%N)
  msg=$("$B" discrepancy --metric star "$T/ten.csv" --max-seconds "$b" 2>&1 >/dev/null)
  e=$(date +%s.%N)
  echo "$s $e $b" | awk '{printf "B = %s s: ended after %.2f s (%.2f B): ", $3, $2 - $1, ($2 - $1) / $3}'
  echo "${msg:-finished}"
done
