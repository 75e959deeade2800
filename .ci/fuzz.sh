#!/usr/bin/env bash
# Builds the libFuzzer target (clang, ASan + UBSan, CGAL's assertions on) in build-fuzz, makes
# its seed corpus from the small OFF files of CGAL's collection (extracted at configure time,
# never committed), and fuzzes for NP_FUZZ_SECONDS (default 60). A crash fails the run and
# leaves the input as build-fuzz/fuzz/crash-*.
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${NP_FUZZ_DIR:-build-fuzz}
start=$SECONDS
cmake -S . -B "$dir" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" \
      -DNP_BUILD_TESTS=OFF -DNP_BUILD_EXAMPLES=OFF -DNP_BUILD_BENCHMARKS=OFF -DNP_BUILD_FUZZER=ON
cmake --build "$dir" -j"${NP_JOBS:-2}" --target fuzz_texture_off
echo "fuzzer build: $((SECONDS - start)) s"
cd "$dir/fuzz"
rm -rf seeds && mkdir -p seeds corpus
find ../data/meshes -name '*.off' -size -4k -exec cp {} seeds \;
export ASAN_OPTIONS=detect_leaks=1
export UBSAN_OPTIONS=print_stacktrace=1
./fuzz_texture_off -max_total_time="${NP_FUZZ_SECONDS:-60}" -max_len=4096 -timeout=30 -rss_limit_mb=4096 \
                   -print_final_stats=1 corpus seeds
