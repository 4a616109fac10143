#!/usr/bin/env bash
# Runs qmckit's no_std core on three emulated Cortex-M boards and checks that it prints
# exactly the same test vectors as the host build; then runs every other firmware variant.
#
#   bash tests/firmware/run.sh          (from any directory; CI calls it from .ci/run)
#
# 1. Builds the host generator (host/, rustup's toolchain) and takes its output as the
#    reference. Both sides print src/vectors.rs, the one list of vectors.
# 2. For each board, cross-builds the vector firmware (common.sh: Debian's rustc-web with
#    -Zbuild-std, rustup's rust-lld), runs it under qemu-system-arm with semihosting and a
#    timeout, requires exit code 0 and `diff -u` against the host output.
#    The same vectors on RISC-V (riscv32imac, qemu-system-riscv32 -M virt; riscv/).
# 3. The firmware author's example (src/bin/baked_pattern.rs: a const-baked pattern and a
#    heapless buffer) on every board: exit 0 and the same output on all of them.
# 4. panic_proof.sh (link-time proof that the hot paths keep no panic) and defmt_check.sh
#    (defmt logging decoded on the host), unless FIRMWARE_SKIP_EXTRAS=1.
#
# Installs nothing except, when missing, the Debian packages qemu-system-arm, rustc-web
# and rust-web-src (apt-get; see common.sh). Exits non-zero on any build failure, QEMU
# failure or timeout, or difference. Environment knobs: FIRMWARE_BOARDS (space-separated
# subset of microbit, lm3s6965evb, mps2-an386, riscv-virt), FIRMWARE_TIMEOUT (seconds a QEMU run,
# default 120).
set -euo pipefail

# shellcheck source=common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
ensure_cross_toolchain

BOARDS=(microbit lm3s6965evb mps2-an386)
TIMEOUT_SECS=${FIRMWARE_TIMEOUT:-120}
OUT="$HERE/target/out"
mkdir -p "$OUT"

echo "firmware: host $(rustc --version); cross /usr/bin/rustc $(/usr/bin/rustc --version | cut -d' ' -f2)"
echo "firmware: $(qemu-system-arm --version | head -n1); linker $LLD"

target_of_board() {
    case "$1" in
    microbit) echo thumbv6m-none-eabi ;;
    lm3s6965evb) echo thumbv7m-none-eabi ;;
    mps2-an386) echo thumbv7em-none-eabihf ;;
    *) return 1 ;;
    esac
}

# A fingerprint of everything the vectors depend on: if qmckit's sources change while
# this script runs (someone editing the tree), host and firmware may differ for that reason.
fingerprint() {
    find "$HERE/../../src" "$HERE/../../build.rs" "$HERE/../../Cargo.toml" "$HERE/src" \
        "$HERE/host/src" -type f -print0 2>/dev/null | sort -z | xargs -0 cat | cksum
}

T_ALL=$(now)
FINGERPRINT=$(fingerprint)

# --- host reference ---------------------------------------------------------------------
T0=$(now)
(cd host && cargo build --release --quiet --target-dir "$HERE/target/host")
"$HERE/target/host/release/qmckit-firmware-host" >"$OUT/host.txt"
HOST_LINES=$(wc -l <"$OUT/host.txt")
if [ "$HOST_LINES" -lt 100 ] || ! tail -n1 "$OUT/host.txt" | grep -qx "end $((HOST_LINES - 1))"; then
    echo "firmware: host output looks wrong ($HOST_LINES lines)" >&2
    exit 1
fi
echo "firmware: host reference: $HOST_LINES lines ($(secs "$T0" "$(now)") s)"

FAILED=()
PASSED=0

# run_variant BOARD BIN FEATURES EXPECTED: builds BIN for BOARD, runs it, and diffs its
# output with the file EXPECTED (or, if EXPECTED does not exist yet, makes it the reference).
run_variant() {
    local board=$1 bin=$2 features=$3 expected=$4
    local target tdir elf out rc=0 t0 t1 t2 timing
    target=$(target_of_board "$board")
    tdir="$HERE/target/$board"
    out="$OUT/$board-$bin.txt"
    echo
    echo "-- firmware $bin on $board ($target)"
    t0=$(now)
    if ! cross_build "$target" "$tdir" "$features" "$bin"; then
        echo "firmware $bin on $board: BUILD FAILED"
        FAILED+=("$bin/$board (build)")
        return 0
    fi
    t1=$(now)
    elf="$tdir/$target/release/$bin"
    run_qemu "$board" "$elf" "$out" "$TIMEOUT_SECS" || rc=$?
    t2=$(now)
    timing="build $(secs "$t0" "$t1") s, qemu $(secs "$t1" "$t2") s"
    echo "   flash: $(flash_size "$elf")"
    if [ "$rc" -ne 0 ]; then
        if [ "$rc" -eq 124 ]; then
            echo "firmware $bin on $board: TIMEOUT after ${TIMEOUT_SECS}s ($timing)"
        else
            echo "firmware $bin on $board: qemu exit code $rc ($timing)"
        fi
        sed 's/^/   stderr: /' "$out.stderr" | tail -n 20
        FAILED+=("$bin/$board (exit $rc)")
        return 0
    fi
    if [ ! -f "$expected" ]; then
        cp "$out" "$expected"
    fi
    if ! diff -u --label expected "$expected" --label "$board" "$out" >"$out.diff"; then
        echo "firmware $bin on $board: OUTPUT DIFFERS from $(basename "$expected") ($timing):"
        head -n 60 "$out.diff"
        FAILED+=("$bin/$board (diff)")
        return 0
    fi
    echo "firmware $bin on $board: $(wc -l <"$out") lines identical to $(basename "$expected") ($timing)"
    PASSED=$((PASSED + 1))
}

rm -f "$OUT/baked-pattern.reference.txt"
for board in "${BOARDS[@]}"; do
    if [ -n "${FIRMWARE_BOARDS:-}" ] && ! [[ " $FIRMWARE_BOARDS " == *" $board "* ]]; then
        continue
    fi
    run_variant "$board" qmckit-firmware "" "$OUT/host.txt"
    # The first board's output is the reference for the others.
    run_variant "$board" baked-pattern heapless "$OUT/baked-pattern.reference.txt"
done

# RISC-V: riscv32imac on QEMU `virt` (riscv/: riscv-rt, RISC-V semihosting), the same
# vectors. Its own crate and target directory; memory.x is passed before riscv-rt's link.x.
if [ -z "${FIRMWARE_BOARDS:-}" ] || [[ " $FIRMWARE_BOARDS " == *" riscv-virt "* ]]; then
    echo
    echo "-- firmware qmckit-firmware-riscv on riscv-virt (riscv32imac-unknown-none-elf)"
    t0=$(now)
    rv_elf="$HERE/riscv/target/riscv32imac-unknown-none-elf/release/qmckit-firmware-riscv"
    if ! (cd riscv && RUSTC=/usr/bin/rustc RUSTC_BOOTSTRAP=1 \
        RUSTFLAGS="-C linker=$LLD -C link-arg=-Tmemory.x -C link-arg=-Tlink.x" \
        cargo build --release --quiet \
        -Zbuild-std=core,compiler_builtins -Zbuild-std-features=compiler-builtins-mem \
        --target riscv32imac-unknown-none-elf); then
        echo "firmware riscv-virt: BUILD FAILED"
        FAILED+=("riscv-virt (build)")
    else
        t1=$(now)
        rc=0
        timeout "$TIMEOUT_SECS" qemu-system-riscv32 -M virt -bios none -nographic -monitor none \
            -semihosting-config enable=on,target=native -kernel "$rv_elf" \
            </dev/null >"$OUT/riscv-virt.txt" 2>"$OUT/riscv-virt.txt.stderr" || rc=$?
        timing="build $(secs "$t0" "$t1") s, qemu $(secs "$t1" "$(now)") s"
        echo "   flash (RAM image): $(flash_size "$rv_elf")"
        if [ "$rc" -ne 0 ]; then
            echo "firmware riscv-virt: qemu exit code $rc ($timing)"
            tail -n 20 "$OUT/riscv-virt.txt.stderr"
            FAILED+=("riscv-virt (exit $rc)")
        elif ! diff -u --label host "$OUT/host.txt" --label riscv-virt "$OUT/riscv-virt.txt" \
            >"$OUT/riscv-virt.diff"; then
            echo "firmware riscv-virt: OUTPUT DIFFERS from host ($timing):"
            head -n 60 "$OUT/riscv-virt.diff"
            FAILED+=("riscv-virt (diff)")
        else
            echo "firmware riscv-virt: $(wc -l <"$OUT/riscv-virt.txt") lines identical to host.txt ($timing)"
            PASSED=$((PASSED + 1))
        fi
    fi
fi

echo
if [ "$(fingerprint)" != "$FINGERPRINT" ]; then
    echo "firmware: WARNING: qmckit's sources changed during this run; rerun before" \
        "trusting a difference"
fi
if [ "$PASSED" -eq 0 ] && [ "${#FAILED[@]}" -eq 0 ]; then
    echo "firmware: no board selected (FIRMWARE_BOARDS='${FIRMWARE_BOARDS:-}')" >&2
    exit 1
fi

if [ "${FIRMWARE_SKIP_EXTRAS:-0}" != 1 ]; then
    echo
    bash "$HERE/panic_proof.sh" || FAILED+=("panic proof")
    echo
    bash "$HERE/defmt_check.sh" || FAILED+=("defmt")
fi

echo
if [ "${#FAILED[@]}" -ne 0 ]; then
    echo "firmware: FAILED: ${FAILED[*]} ($PASSED variant run(s) identical; outputs in $OUT)"
    exit 1
fi
echo "firmware: all $PASSED variant runs identical to their reference in $(secs "$T_ALL" "$(now)") s"
