#!/usr/bin/env bash
# qmckit's `defmt::Format` on a Cortex-M3 under QEMU, decoded on the host.
#
#   bash tests/firmware/defmt_check.sh      (run.sh calls it)
#
# Builds src/bin/defmt_log.rs (feature `defmt`: qmckit's derived `defmt::Format`, logged
# through defmt-semihosting) for lm3s6965evb, runs it under QEMU, decodes the binary log with
# `defmt-print` (installed with `cargo install defmt-print --locked` when missing) and diffs
# the text with the host's `Debug` rendering of the same values
# (host/src/bin/defmt_expected.rs, from the same src/defmt_lines.rs). Exits non-zero on any
# failure or difference.
set -euo pipefail

# shellcheck source=common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
ensure_cross_toolchain

OUT="$HERE/target/out/defmt"
mkdir -p "$OUT"

if ! command -v defmt-print >/dev/null 2>&1; then
    echo "defmt: installing defmt-print (cargo install --locked)"
    cargo install defmt-print --locked --quiet
fi

(cd host && cargo build --release --quiet --bin defmt_expected --target-dir "$HERE/target/host")
"$HERE/target/host/release/defmt_expected" >"$OUT/expected.txt"

board=lm3s6965evb
target=thumbv7m-none-eabi
tdir="$HERE/target/$board"
cross_build "$target" "$tdir" defmt defmt-log
elf="$tdir/$target/release/defmt-log"
if ! run_qemu "$board" "$elf" "$OUT/log.bin" 60; then
    echo "defmt: the firmware did not exit 0 under QEMU" >&2
    cat "$OUT/log.bin.stderr" >&2
    exit 1
fi
defmt-print --log-format '{s}' -e "$elf" <"$OUT/log.bin" >"$OUT/decoded.txt" 2>"$OUT/decode.stderr" || {
    echo "defmt: defmt-print failed" >&2
    cat "$OUT/decode.stderr" >&2
    exit 1
}
if ! diff -u --label host-Debug "$OUT/expected.txt" --label defmt-decoded "$OUT/decoded.txt"; then
    echo "defmt: the decoded log differs from the host's Debug output" >&2
    exit 1
fi
echo "defmt: $(wc -l <"$OUT/decoded.txt") lines logged with defmt on $board ($(wc -c <"$OUT/log.bin") bytes" \
    "on the wire) decode to exactly the host's Debug text"
