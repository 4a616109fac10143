#!/usr/bin/env bash
# A dependent that asks qmckit for nothing (default features) must not pull rayon, rustfft
# or plotters: a program that only samples gets the sampling core. Makes a throwaway crate
# that depends on this checkout by path and reads its dependency tree.
# Usage: scripts/check_default_deps.sh [WORK_DIR]   (default target/dep-check)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
dir=${1:-$root/target/dep-check}
rm -rf "$dir"
mkdir -p "$dir/src"
cat >"$dir/Cargo.toml" <<TOML
[package]
name = "dep-check"
version = "0.0.0"
edition = "2024"
publish = false

[workspace]

[dependencies]
qmckit = { path = "$root" }
TOML
echo 'fn main() {}' >"$dir/src/main.rs"
tree=$(cd "$dir" && cargo tree -e normal --prefix none)
echo "$tree" | sort -u
if echo "$tree" | grep -Eq '^(rayon|rustfft|plotters)[ -]'; then
    echo "a dependent with default features pulls rayon, rustfft or plotters" >&2
    exit 1
fi
echo "default features: no rayon, rustfft or plotters"
