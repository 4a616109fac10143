#!/usr/bin/env bash
# Link-time proof that qmckit's hot paths keep no panic (src/bin/panic_proof.rs).
#
#   bash tests/firmware/panic_proof.sh      (run.sh calls it)
#
# The proof binary's panic handler calls a symbol that is defined nowhere, so it links only
# if no panic path is reachable from the calls it makes. It is linked for thumbv6m,
# thumbv7m and thumbv7em at the firmware release profile (opt-level "s"), and for thumbv7em
# also at opt-level 3 (profile proof-o3), and each linked binary runs under QEMU and must exit 0 (the validated
# constructors succeeded). When a link fails, every check is linked alone to name the
# culprit(s). Exits non-zero on any failure.
set -euo pipefail

# shellcheck source=common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
ensure_cross_toolchain

OUT="$HERE/target/out/panic-proof"
mkdir -p "$OUT"
CHECKS=()
while IFS= read -r name; do CHECKS+=("$name"); done < <(
    sed -n '/proof-checks-begin/,/proof-checks-end/s/^    "\(.*\)",$/\1/p' src/bin/panic_proof.rs)
[ "${#CHECKS[@]}" -gt 0 ] || { echo "panic proof: no checks found" >&2; exit 1; }

FAILED=()
for target in thumbv6m-none-eabi thumbv7m-none-eabi thumbv7em-none-eabihf; do
    board=$(board_of_target "$target")
    # opt-level "s" (the firmware profile) everywhere; opt-level 3 on the Cortex-M4F (a
    # different inliner can keep or drop different panic paths; one target keeps CI short).
    profiles=(release)
    [ "$target" = thumbv7em-none-eabihf ] && profiles+=(proof-o3)
    for profile in "${profiles[@]}"; do
        tdir="$HERE/target/$board" # shares the release build of core with run.sh
        log="$OUT/$target-$profile.log"
        if FIRMWARE_PROFILE=$profile QMCKIT_PROOF_ONLY=all cross_build "$target" "$tdir" "" \
            panic-proof >"$log" 2>&1; then
            elf="$tdir/$target/$profile/panic-proof"
            if run_qemu "$board" "$elf" "$OUT/$target-$profile.txt" 60; then
                echo "panic proof: $target $profile: linked without a panic path," \
                    "${#CHECKS[@]} checks, ran OK"
            else
                echo "panic proof: $target $profile: linked, but did not exit 0 under QEMU"
                FAILED+=("$target/$profile (run)")
            fi
            continue
        fi
        if ! grep -q qmckit_panic_path_survived "$log"; then
            echo "panic proof: $target $profile: BUILD FAILED"
            tail -n 30 "$log"
            FAILED+=("$target/$profile (build)")
            continue
        fi
        culprits=()
        for check in "${CHECKS[@]}"; do
            if ! FIRMWARE_PROFILE=$profile QMCKIT_PROOF_ONLY=$check cross_build "$target" \
                "$tdir" "" panic-proof >/dev/null 2>&1; then
                culprits+=("$check")
            fi
        done
        echo "panic proof: $target $profile: a PANIC PATH survives; alone, these keep one:" \
            "${culprits[*]:-(none alone: an interaction)}"
        FAILED+=("$target/$profile")
    done
done
if [ "${#FAILED[@]}" -ne 0 ]; then
    echo "panic proof: FAILED: ${FAILED[*]}"
    exit 1
fi
echo "panic proof: every hot path is panic-free on 3 targets at opt-level s, and at 3 on thumbv7em"
