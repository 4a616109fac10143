#!/usr/bin/env bash
# Calibration table of the analysis commands' time estimates (release build).
#
# For each row: the estimate, parsed from the refusal at a tiny --max-seconds (every
# analysis command names its estimate there: "estimated X s"), the measured wall time of
# the same command under a generous budget, and real/estimate (the goal: 0.5 to 2).
# Then one run whose estimate is low (a budget far below the real time, admitted because
# the estimate is checked against the budget and the deadline is 1.25 B): it must end with
# the one-line OutOfTime error within about 1.5 B.
#
# Usage: scripts/budget_table_analysis.sh [path/to/qmckit]   (about three minutes)
set -u
B=${1:-target/release/qmckit}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT

pts() { # name n d [sampler]
  "$B" points "${4:-sobol}" -n "$2" -d "$3" --format csv > "$T/$1.csv"
}

estimate() { # args...: the estimate in seconds, from the refusal at --max-seconds 1e-9
  "$B" "$@" --max-seconds 1e-9 2>&1 >/dev/null | grep -o 'estimated [0-9.e+-]* s' | head -1 |
    awk '{print $2}'
}

measure() { # args...: wall seconds under a budget of 600 s
  local s e
  s=$(date +%s.%N)
  "$B" "$@" --max-seconds 600 > /dev/null 2> "$T/err" || { echo "FAIL: $(cat "$T/err")" >&2; }
  e=$(date +%s.%N)
  echo "$s $e" | awk '{printf "%.3f", $2 - $1}'
}

row() { # label args...
  local label=$1; shift
  local est real
  est=$(estimate "$@")
  real=$(measure "$@")
  if [ -z "$est" ]; then est=0; fi
  printf "| %-44s " "$label"
  echo "$est $real" | awk '{ if ($1 > 0) r = sprintf("%5.2f", $2 / $1); else r = "-";
    printf "| %9.3f | %8.3f | %s |\n", $1, $2, r }'
}

echo "| command | estimate (s) | real (s) | real/estimate |"
echo "|---|---:|---:|---:|"
# Exact star discrepancy, d = 2..8 (N^2 sweep in 2D, the decomposition above).
for nd in "20000 2" "8000 2" "12000 3" "20000 3" "2500 4" "4000 4" "800 5" "1100 5" \
          "300 6" "400 6" "160 7" "200 7" "90 8" "120 8"; do
  set -- $nd
  pts "s$1_$2" "$1" "$2"
  row "discrepancy star N=$1 d=$2" discrepancy --metric star "$T/s$1_$2.csv"
done
# L2 family (pair sums), d = 8.
pts l2 30000 8
row "discrepancy cd N=30000 d=8" discrepancy --metric cd "$T/l2.csv"
row "discrepancy l2-star N=30000 d=8" discrepancy --metric l2-star "$T/l2.csv"
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
# t-value by counting (scrambled) and by the rank test.
row "tvalue sobol m=16 d=4 scramble owen" tvalue sobol -m 16 -d 4 --scramble owen
row "tvalue sobol m=20 d=4 scramble owen" tvalue sobol -m 20 -d 4 --scramble owen

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
for b in 2 4; do
  s=$(date +%s.%N)
  msg=$("$B" discrepancy --metric star "$T/ten.csv" --max-seconds "$b" 2>&1 >/dev/null)
  e=$(date +%s.%N)
  echo "$s $e $b" | awk '{printf "B = %s s: ended after %.2f s (%.2f B): ", $3, $2 - $1, ($2 - $1) / $3}'
  echo "${msg:-finished}"
done
