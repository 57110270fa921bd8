#!/bin/sh
# Bounded fuzzing of the M3G Loader: scripts/fuzz-loader.sh [SECONDS] (default 60), split
# between the targets: m3g_loader (one file: load, save, reload, render) and
# m3g_references (several files in an in-memory file system referring to each other:
# load, render). Seeds libFuzzer with the .m3g corpus in tests/data/m3g and fails on
# any crash, panic, timeout (10 s per input) or a resident size over 512 MiB. Needs the
# nightly toolchain and cargo-fuzz; installs them through rustup and cargo when they are
# missing. cargo-fuzz compiles everything as one codegen unit, so the build runs on one
# core; with AddressSanitizer it took 44.5 of CI's 73 minutes. The build is therefore
# without it (`-s none`: the Loader and the rasterizer have no unsafe code for it to
# check; panics, overflow checks, timeouts and the memory limit find the bugs here) and
# without the rasterizer's instruction-set clones (`cfg(fuzzing)`, see
# crates/core/Cargo.toml): 9.7 minutes.
set -eu
cd "$(dirname "$0")/.."
seconds=${1:-60}
each=$((seconds / 2))
[ "$each" -ge 1 ] || each=1
rustup run nightly rustc --version >/dev/null 2>&1 ||
    rustup toolchain install nightly --profile minimal
command -v cargo-fuzz >/dev/null 2>&1 || cargo install --locked cargo-fuzz
for target in m3g_loader m3g_references; do
    corpus=fuzz/corpus/$target
    mkdir -p "$corpus"
    cp tests/data/m3g/*.m3g "$corpus"/
done
# A seed of the references target: a file whose external reference names the next file.
printf '\n--\n' >fuzz/corpus/m3g_references/.sep
cat tests/data/m3g/memory.m3g fuzz/corpus/m3g_references/.sep \
    tests/data/m3g/cube.m3g >fuzz/corpus/m3g_references/memory-then-cube
rm fuzz/corpus/m3g_references/.sep
cd fuzz
for target in m3g_loader m3g_references; do
    cargo +nightly fuzz run -s none "$target" "corpus/$target" -- \
        -max_total_time="$each" -timeout=10 -rss_limit_mb=512 \
        -print_final_stats=1
done
