#!/bin/sh
# Bounded fuzzing of the M3G Loader: scripts/fuzz-loader.sh [SECONDS] (default 60).
# Seeds libFuzzer with the .m3g corpus in ../shared/m3g-corpus and fails on any crash,
# panic, timeout (10 s per input) or allocation over 512 MiB. Needs the nightly toolchain
# and cargo-fuzz; installs them through rustup and cargo when they are missing.
set -eu
cd "$(dirname "$0")/.."
seconds=${1:-60}
rustup run nightly rustc --version >/dev/null 2>&1 ||
    rustup toolchain install nightly --profile minimal
command -v cargo-fuzz >/dev/null 2>&1 || cargo install --locked cargo-fuzz
corpus=fuzz/corpus/m3g_loader
mkdir -p "$corpus"
cp ../shared/m3g-corpus/*.m3g "$corpus"/
cd fuzz
cargo +nightly fuzz run m3g_loader "corpus/m3g_loader" -- \
    -max_total_time="$seconds" -timeout=10 -rss_limit_mb=512 -malloc_limit_mb=512 \
    -print_final_stats=1
