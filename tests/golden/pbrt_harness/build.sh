#!/bin/sh
# Compiles driver.cpp against a pbrt-v4 checkout and writes the pixel-sampler goldens.
#
#   tests/golden/pbrt_harness/build.sh PBRT_V4_DIR [OUT]
#
# PBRT_V4_DIR is a checkout of https://github.com/mmp/pbrt-v4 (no submodules needed), e.g.
#   git clone https://github.com/mmp/pbrt-v4 && git -C pbrt-v4 checkout 5f7a6068
# OUT defaults to tests/golden/pbrt_samplers_compiled.txt. Needs g++ (C++17).
#
# What is compiled from pbrt: its headers (samplers.h and what it includes), the
# HaltonSampler constructor cut out of src/pbrt/samplers.cpp (the rest of that file pulls in
# cameras, media and OpenVDB), util/primes.cpp (the prime table), util/lowdiscrepancy.cpp
# (ComputeRadicalInversePermutations), util/sobolmatrices.cpp and util/pstd.cpp (the
# allocator). Stubbed (stubs.cpp): LogFatal, Warning and the two printf functions of util/print.cpp,
# which only error paths and ToString reach; they abort if called.
set -eu
PBRT=${1:?usage: build.sh PBRT_V4_DIR [OUT]}
HERE=$(cd "$(dirname "$0")" && pwd)
OUT=${2:-$HERE/../pbrt_samplers_compiled.txt}
SRC=$PBRT/src/pbrt
test -f "$SRC/samplers.h" || { echo "no src/pbrt/samplers.h under $PBRT" >&2; exit 1; }
COMMIT=$(git -C "$PBRT" rev-parse HEAD 2>/dev/null || echo "${PBRT_COMMIT:-unknown}")
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

# The constructor, verbatim from pbrt's samplers.cpp, in a unit that includes only samplers.h.
awk '/^HaltonSampler::HaltonSampler\(/{f=1} f{print} f&&/^}/{exit}' "$SRC/samplers.cpp" \
    >"$WORK/halton_ctor.inc"
test -s "$WORK/halton_ctor.inc" || { echo "HaltonSampler constructor not found" >&2; exit 1; }
printf '#include <pbrt/samplers.h>\nnamespace pbrt {\n#include "halton_ctor.inc"\n}\n' \
    >"$WORK/halton_ctor.cpp"

CXX=${CXX:-g++}
# -ffp-contract=off: no fused multiply-adds (pbrt's float arithmetic as written).
FLAGS="-std=c++17 -O2 -ffp-contract=off -DNDEBUG -DPBRT_IS_LINUX -DPBRT_HAVE_POSIX_MEMALIGN -I$PBRT/src -I$PBRT/src/ext -I$WORK"
for f in "$HERE/driver.cpp" "$HERE/stubs.cpp" "$WORK/halton_ctor.cpp" \
    "$SRC/util/primes.cpp" "$SRC/util/lowdiscrepancy.cpp" "$SRC/util/sobolmatrices.cpp" \
    "$SRC/util/pstd.cpp"; do
    $CXX $FLAGS -c "$f" -o "$WORK/$(basename "$f" .cpp).o"
done
$CXX "$WORK"/*.o -o "$WORK/driver"
{
    echo "# pbrt-v4 pixel samplers, printed by tests/golden/pbrt_harness/driver.cpp compiled"
    echo "# against pbrt-v4 at commit $COMMIT (tests/golden/pbrt_harness/build.sh)."
    echo "# Each line: config id, x, y, i, then f32 bit patterns (hex) in driver.cpp's order."
    "$WORK/driver"
} >"$OUT"
echo "wrote $OUT ($(wc -l <"$OUT") lines) from pbrt-v4 $COMMIT" >&2
