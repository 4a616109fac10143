#!/usr/bin/env bash
# Flash, RAM and instructions per sample of qmckit's no_std core on Cortex-M, written to
# tests/firmware/SIZES.md (generated; do not edit) and printed.
#
#   bash tests/firmware/size_report.sh            (from any directory; CI calls it)
#
# 1. Sizes. Builds the minimal binaries src/bin/size_*.rs (cortex-m-rt + a semihosting exit
#    + one use of the library, run-time indices through black_box) for thumbv6m-none-eabi
#    (microbit's memory map) and thumbv7em-none-eabihf (mps2-an386's), release profile
#    (opt-level "s", fat LTO, panic = "abort"). Flash = .vector_table + .text + .rodata
#    + .data (its load image); RAM = .data + .bss + the stack's high-water mark, measured by
#    running a second build with the `stack-probe` feature (paints the free stack, reports
#    the deepest word touched) under QEMU. Every binary is also run once and must exit 0.
#    The baseline binary's figures are subtracted so the library's own cost shows.
# 2. Instructions. Runs src/bin/icount.rs on the Cortex-M0, M3 and M4F boards with
#    `-icount shift=0,sleep=off` (QEMU's virtual clock advances 1 ns an instruction),
#    timing each workload with SysTick and converting ticks to instructions with a
#    calibration loop of known length (see icount.rs). Each board runs twice; the two
#    outputs must be identical (the count is deterministic).
#
# Installs nothing but the Debian cross toolchain when missing (see common.sh). Exits
# non-zero on a build failure, a binary that does not exit 0, or non-repeatable counts.
# SIZE_REPORT_OUT overrides the output file (default: SIZES.md next to this script).
set -euo pipefail

# shellcheck source=common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
ensure_cross_toolchain

OUT="$HERE/target/out/size"
REPORT=${SIZE_REPORT_OUT:-$HERE/SIZES.md}
mkdir -p "$OUT"
T_ALL=$(now)

SIZE_TARGETS=(thumbv6m-none-eabi thumbv7em-none-eabihf)
# id|binary|extra features|description (markdown)
CONFIGS=(
    "baseline|size-baseline||baseline: cortex-m-rt, semihosting exit, empty loop"
    "ri3|size-radical-inverse||(a) radical inverse, base 3 (\`const\` \`RadicalInverse\`)"
    "ri-rt|size-radical-inverse-rt||(a') radical inverse, base chosen at run time"
    "sobol-owen2|size-sobol-owen2||(b) 2D Sobol' + \`FastOwen\` (\`SobolDimension\` consts)"
    "sobol-owen2-gf2|size-sobol-owen2-gf2||(b') 2D Sobol' + \`FastOwen\`, 2 dims' directions copied, \`gf2_mul\`"
    "sobol64|size-sobol-dims||(c) Sobol', run-time dimension, 64 dims compiled in"
    "sobol1024|size-sobol-dims|sobol-dims-1024|(c) Sobol', run-time dimension, 1024 dims (\`sobol-dims-1024\`)"
)

# --- sizes ------------------------------------------------------------------------------
declare -A FLASH RAM
SIZE_ROWS=()
GOAL_LINES=()
for target in "${SIZE_TARGETS[@]}"; do
    board=$(board_of_target "$target")
    tdir="$HERE/target/$board"
    for cfg in "${CONFIGS[@]}"; do
        IFS='|' read -r id bin features desc <<<"$cfg"
        elf="$tdir/$target/release/$bin"
        echo "size: $target $id"
        cross_build "$target" "$tdir" "$features" "$bin"
        cp "$elf" "$OUT/$target-$id.elf"
        if ! run_qemu "$board" "$OUT/$target-$id.elf" "$OUT/$target-$id.txt" 60; then
            echo "size: $target $id: the binary did not exit 0 under QEMU" >&2
            cat "$OUT/$target-$id.txt.stderr" >&2
            exit 1
        fi
        read -r vt text rodata data bss < <(section_sizes "$OUT/$target-$id.elf")
        # The same program with the stack probe, for the stack's high-water mark.
        cross_build "$target" "$tdir" "${features:+$features,}stack-probe" "$bin"
        cp "$elf" "$OUT/$target-$id-probe.elf"
        if ! run_qemu "$board" "$OUT/$target-$id-probe.elf" "$OUT/$target-$id-probe.txt" 60; then
            echo "size: $target $id (stack probe): did not exit 0 under QEMU" >&2
            exit 1
        fi
        stack=$(sed -n 's/^stack \([0-9]*\)$/\1/p' "$OUT/$target-$id-probe.txt")
        [ -n "$stack" ] || { echo "size: $target $id: no stack figure" >&2; exit 1; }
        flash=$((vt + text + rodata + data))
        ram=$((data + bss + stack))
        FLASH[$target-$id]=$flash
        RAM[$target-$id]=$ram
        base_flash=${FLASH[$target-baseline]}
        base_ram=${RAM[$target-baseline]}
        if [ "$id" = baseline ]; then
            lib_flash="—"
            lib_ram="—"
        else
            lib_flash="**$((flash - base_flash))**"
            lib_ram=$((ram - base_ram))
            # A smaller frame than the baseline's main (codegen noise): shown as 0.
            [ "$lib_ram" -ge 0 ] || lib_ram="0 ($lib_ram)"
        fi
        SIZE_ROWS+=("| $desc | \`$target\` | $text | $rodata | $flash | $lib_flash | $((data + bss)) | $stack | $lib_ram |")
    done
done
v6=thumbv6m-none-eabi
for id in sobol-owen2 sobol-owen2-gf2; do
    cost=$((FLASH[$v6-$id] - FLASH[$v6-baseline]))
    verdict=$([ "$cost" -le 1536 ] && echo "met" || echo "**not met**")
    GOAL_LINES+=("- \`$id\` on $v6: $cost bytes of flash over the baseline: $verdict")
done

# --- instructions -----------------------------------------------------------------------
ICOUNT_BOARDS=("microbit:thumbv6m-none-eabi:Cortex-M0" "lm3s6965evb:thumbv7m-none-eabi:Cortex-M3"
    "mps2-an386:thumbv7em-none-eabihf:Cortex-M4F")
declare -A IPS # board:workload -> "gross net"
HEADER="| workload |"
RULE="|---|"
for entry in "${ICOUNT_BOARDS[@]}"; do
    IFS=':' read -r board target core <<<"$entry"
    echo "icount: $core ($board)"
    tdir="$HERE/target/$board"
    cross_build "$target" "$tdir" "" icount
    cp "$tdir/$target/release/icount" "$OUT/icount-$board.elf"
    for run in 1 2; do
        if ! QEMU_EXTRA="-icount shift=0,sleep=off" \
            run_qemu "$board" "$OUT/icount-$board.elf" "$OUT/icount-$board-$run.txt" 120; then
            echo "icount: $board run $run failed" >&2
            cat "$OUT/icount-$board-$run.txt.stderr" >&2
            exit 1
        fi
    done
    if ! cmp -s "$OUT/icount-$board-1.txt" "$OUT/icount-$board-2.txt"; then
        echo "icount: $board: two runs differ (counts not repeatable)" >&2
        diff "$OUT/icount-$board-1.txt" "$OUT/icount-$board-2.txt" >&2 || true
        exit 1
    fi
    # Instructions a tick from the two calibration runs (2 instructions an iteration), then
    # per sample: gross = ticks * k / samples; net = gross - the empty loop's (same index
    # width; the fill has no per-sample loop of its own, so its gross is its cost).
    while read -r key gross net; do
        IPS[$board:$key]="$gross $net"
    done < <(awk '
        $1 == "calib" { n[++c] = $2; t[c] = $3 }
        $1 == "dwt" { dwt = $2 }
        $1 == "work" { name[++w] = $2; cnt[w] = $3; tk[w] = $4 }
        END {
            k = 2 * (n[2] - n[1]) / (t[2] - t[1])
            printf "_k %.3f %d\n", k, dwt
            for (j = 1; j <= w; j++) g[name[j]] = tk[j] * k / cnt[j]
            for (j = 1; j <= w; j++) {
                s = name[j]; e = ""
                if (s ~ /-16bit$/) e = "empty-loop-16bit"
                if (s ~ /-32bit$/) e = "empty-loop-32bit"
                net = (e == "") ? g[s] : g[s] - g[e]
                printf "%s %.1f %.1f\n", s, g[s], net
            }
        }' "$OUT/icount-$board-1.txt")
    HEADER+=" $core ($board) |"
    RULE+="---|"
done

WORKLOADS=(
    "empty-loop-16bit|empty reference loop (index, \`black_box\`, XOR)"
    "radical-inverse-3-16bit|radical inverse base 3, \`RadicalInverse::sample\`, 16-bit indices"
    "radical-inverse-3-32bit|radical inverse base 3, 32-bit indices"
    "sobol-2d-16bit|2D Sobol' point, \`SobolDimension::sample\` x2, 16-bit indices"
    "sobol-2d-32bit|2D Sobol' point, \`SobolDimension::sample\` x2, 32-bit indices"
    "sobol-2d-table-16bit|2D Sobol' point, \`SobolTable::sample\` x2 (8 KiB of tables), 16-bit indices"
    "sobol-2d-fill64|2D Sobol' point, \`Sampler::fill\` of \`Sobol\` (64-point blocks, sequential)"
    "sobol-2d-owen-16bit|2D Owen-scrambled Sobol' point, \`SobolDimension\` + \`FastOwen::scramble\`, 16-bit"
    "sobol-2d-owen-32bit|2D Owen-scrambled Sobol' point, same, 32-bit indices"
    "owen-sobol4-4d-16bit|4D Owen-scrambled Sobol' point, \`OwenSobol::sample4\` (16 KiB of shared tables)"
)
ICOUNT_ROWS=()
for wl in "${WORKLOADS[@]}"; do
    IFS='|' read -r key desc <<<"$wl"
    row="| $desc |"
    for entry in "${ICOUNT_BOARDS[@]}"; do
        board=${entry%%:*}
        read -r gross net <<<"${IPS[$board:$key]:-? ?}"
        if [[ "$key" == empty-loop* || "$key" == *fill64 ]]; then
            row+=" $gross |"
        else
            row+=" $gross ($net) |"
        fi
    done
    ICOUNT_ROWS+=("$row")
done
CAL_LINE=""
for entry in "${ICOUNT_BOARDS[@]}"; do
    IFS=':' read -r board target core <<<"$entry"
    read -r k dwt <<<"${IPS[$board:_k]}"
    CAL_LINE+="$core: $k instructions a SysTick tick (DWT CYCCNT counting: $([ "$dwt" = 1 ] && echo yes || echo no)). "
done
m3_sobol=$(awk '{ print $1 }' <<<"${IPS[lm3s6965evb:sobol-2d-16bit]}")
m3_table=$(awk '{ print $1 }' <<<"${IPS[lm3s6965evb:sobol-2d-table-16bit]}")
m3_fill=$(awk '{ print $1 }' <<<"${IPS[lm3s6965evb:sobol-2d-fill64]}")
goal() { awk -v x="$1" 'BEGIN { print (x <= 40) ? "met" : "**not met**" }'; }

# --- report -----------------------------------------------------------------------------
{
    echo "# qmckit on Cortex-M: flash, RAM and instructions per sample"
    echo
    echo "Generated by \`bash tests/firmware/size_report.sh\` (do not edit by hand):"
    echo "$(/usr/bin/rustc --version) with \`-Zbuild-std\`, $(qemu-system-arm --version | head -n1 | sed 's/ (.*//')."
    echo "Release profile of the firmware crate: opt-level \"s\", fat LTO, one codegen unit,"
    echo "\`panic = \"abort\"\`. The programs are in \`tests/firmware/src/bin/\`."
    echo
    echo "## Flash and RAM"
    echo
    echo "Flash = \`.vector_table\` + \`.text\` + \`.rodata\` + \`.data\`; RAM = \`.data\` + \`.bss\` +"
    echo "the stack's high-water mark (measured under QEMU by painting the free stack). The"
    echo "*library* columns subtract the baseline binary of the same target, so they show what"
    echo "the qmckit calls add (code, tables and any compiler-builtins routines they pull in)."
    echo "All sizes in bytes. A stack peak a few words below the baseline's is codegen noise"
    echo "(a different frame for \`main\`); such a library RAM is shown as 0 (raw difference)."
    echo
    echo "| configuration | target | .text | .rodata | flash | library flash | .data+.bss | stack peak | library RAM |"
    echo "|---|---|---:|---:|---:|---:|---:|---:|---:|"
    printf '%s\n' "${SIZE_ROWS[@]}"
    echo
    echo "Goal: 2D Sobol' with Owen scrambling in at most 1.5 KiB (1536 bytes) of flash on"
    echo "thumbv6m."
    echo
    printf '%s\n' "${GOAL_LINES[@]}"
    echo
    echo "(b) uses the public API as documented: \`SobolDimension\` holds its 128 bytes of"
    echo "direction numbers by value, so a \`const\` dimension links only its own numbers, not"
    echo "the compiled-in table (8 KiB, 128 KiB with \`sobol-dims-1024\`). (b') copies the two"
    echo "dimensions' direction numbers into firmware constants and calls \`bits::gf2_mul\`"
    echo "directly (the same bits as \`SobolDimension::sample\`), as a cross-check of (b)."
    echo
    echo "## Instructions per sample"
    echo
    echo "QEMU with \`-icount shift=0,sleep=off\`: the virtual clock advances exactly 1 ns per"
    echo "guest instruction, and SysTick (core clock) counts virtual time, so ticks are"
    echo "proportional to instructions executed. The factor is calibrated on each board with a"
    echo "\`subs\`/\`bne\` loop of two lengths (2 instructions an iteration). QEMU does not model"
    echo "DWT CYCCNT (checked on the M3/M4F: it does not count) nor pipeline timing:"
    echo "these are instruction counts, not cycles. Each board runs twice with identical output."
    echo "$CAL_LINE"
    echo
    echo "Each workload runs 4096 times in a loop over \`black_box\`ed indices (16-bit: 0, 16,"
    echo "32, ..., 65520; 32-bit: a Weyl sequence over the full range). Cells: instructions per"
    echo "sample (or point), loop included, and in parentheses without the empty loop's cost."
    echo
    echo "$HEADER"
    echo "$RULE"
    printf '%s\n' "${ICOUNT_ROWS[@]}"
    echo
    echo "Goal: unscrambled 2D Sobol' at most 40 instructions per point on Cortex-M3 for 16-bit"
    echo "indices, loop included:"
    echo
    echo "- \`SobolDimension::sample\` (no tables, random access): $m3_sobol: $(goal "$m3_sobol")"
    echo "- \`SobolTable::sample\` (4 KiB of tables a dimension, random access): $m3_table: $(goal "$m3_table")"
    echo "- \`Sampler::fill\` (sequential, 64-point blocks): $m3_fill: $(goal "$m3_fill")"
} >"$REPORT"

echo
cat "$REPORT"
echo
echo "size report: wrote $REPORT in $(secs "$T_ALL" "$(now)") s"
