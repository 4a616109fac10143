#!/bin/sh
# Pixel samplers side by side in one process: qmckit's, pbrt-v4's and OpenQMC's, on a 256 x 256
# image, 16 samples a pixel, two 2D draws a sample as f32 (ns per 4D sample, best of N
# interleaved rounds).
#
#   scripts/bench_pixel_peers.sh PBRT_V4_DIR OPENQMC_DIR [ROUNDS] [CPU] [ROWS]
#
# PBRT_V4_DIR: a checkout of https://github.com/mmp/pbrt-v4 (src/pbrt is enough; the data
# files util/pmj02tables.cpp and util/bluenoise.cpp are not used). OPENQMC_DIR: a checkout
# of https://github.com/AcademySoftwareFoundation/openqmc (include/ is enough). Neither is
# copied into this repository. ROUNDS defaults to 15, CPU (the core to pin to with taskset)
# to 1; ROWS, substrings separated by |, keeps only the rows whose names contain one.
# PIXEL_PEERS_CPU_TIME=1 times each row by the thread's CPU time instead of the wall clock
# (on a shared machine: time other jobs take on the core is not counted). CXXFLAGS adds flags to the peers' g++ -O3 (e.g. CXXFLAGS=-march=native; then pass
# RUSTFLAGS="-C target-cpu=native" too for a like-for-like build).
#
# What is built: scripts/bench_pixel_peers/peers.cpp (pbrt's and OpenQMC's samplers behind
# a C interface) and tables.cpp, with pbrt's util/primes.cpp, util/lowdiscrepancy.cpp,
# util/sobolmatrices.cpp, util/pstd.cpp, the HaltonSampler and PMJ02BNSampler constructors
# cut out of samplers.cpp, and tests/golden/pbrt_harness/stubs.cpp, into a static library
# that examples/pixel_peers.rs links (cargo rustc --cfg qmckit_peers).
set -eu
PBRT=${1:?usage: bench_pixel_peers.sh PBRT_V4_DIR OPENQMC_DIR [ROUNDS] [CPU]}
OQMC=${2:?usage: bench_pixel_peers.sh PBRT_V4_DIR OPENQMC_DIR [ROUNDS] [CPU]}
ROUNDS=${3:-15}
CPU=${4:-1}
ROWS=${5:-}
HERE=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$HERE/.." && pwd)
SRC=$PBRT/src/pbrt
test -f "$SRC/samplers.h" || { echo "no src/pbrt/samplers.h under $PBRT" >&2; exit 1; }
test -f "$OQMC/include/oqmc/oqmc.h" || { echo "no include/oqmc/oqmc.h under $OQMC" >&2; exit 1; }
PBRT_COMMIT=$(git -C "$PBRT" rev-parse --short=8 HEAD 2>/dev/null || echo "${PBRT_COMMIT:-unknown}")
OQMC_COMMIT=$(git -C "$OQMC" rev-parse --short=8 HEAD 2>/dev/null || echo "${OQMC_COMMIT:-unknown}")
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

for ctor in HaltonSampler PMJ02BNSampler; do
    awk "/^$ctor::$ctor\\(/{f=1} f{print} f&&/^}/{exit}" "$SRC/samplers.cpp" >"$WORK/$ctor.inc"
    test -s "$WORK/$ctor.inc" || { echo "$ctor constructor not found" >&2; exit 1; }
done
printf '#include <pbrt/samplers.h>\nnamespace pbrt {\n#include "HaltonSampler.inc"\n#include "PMJ02BNSampler.inc"\n}\n' \
    >"$WORK/ctors.cpp"

CXX=${CXX:-g++}
# -ffp-contract=off: pbrt's float arithmetic as written (its floats are compared bit for bit).
FLAGS="-std=c++17 -O3 -ffp-contract=off -DNDEBUG -DPBRT_IS_LINUX -DPBRT_HAVE_POSIX_MEMALIGN ${CXXFLAGS:-}"
INC="-I$PBRT/src -I$PBRT/src/ext -I$OQMC/include -I$WORK"
for f in "$HERE/bench_pixel_peers/peers.cpp" "$HERE/bench_pixel_peers/tables.cpp" \
    "$ROOT/tests/golden/pbrt_harness/stubs.cpp" "$WORK/ctors.cpp" \
    "$SRC/util/primes.cpp" "$SRC/util/lowdiscrepancy.cpp" "$SRC/util/sobolmatrices.cpp" \
    "$SRC/util/pstd.cpp"; do
    $CXX $FLAGS $INC -c "$f" -o "$WORK/$(basename "$f" .cpp).o"
done
ar rcs "$WORK/libpixelpeers.a" "$WORK"/*.o

cd "$ROOT"
CARGO_BUILD_JOBS=${CARGO_BUILD_JOBS:-1} cargo rustc --release -p qmckit --example pixel_peers -- \
    --cfg qmckit_peers -L "native=$WORK" -l static=pixelpeers -l dylib=stdc++
BIN=$(cargo metadata --format-version 1 --no-deps | sed -n 's/.*"target_directory":"\([^"]*\)".*/\1/p')/release/examples/pixel_peers
echo "pbrt-v4 $PBRT_COMMIT, OpenQMC $OQMC_COMMIT, $($CXX --version | head -1) -O3 ${CXXFLAGS:-}, $(rustc --version)"
if command -v taskset >/dev/null; then
    taskset -c "$CPU" "$BIN" "$ROUNDS" "$ROWS"
else
    "$BIN" "$ROUNDS" "$ROWS"
fi
