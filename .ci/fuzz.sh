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
      -DNP_BUILD_TESTS=OFF -DNP_BUILD_EXAMPLES=OFF -DNP_BUILD_TOOLS=OFF -DNP_BUILD_BENCHMARKS=OFF -DNP_BUILD_PYTHON=OFF -DNP_BUILD_FUZZER=ON
cmake --build "$dir" -j"${NP_JOBS:-2}" --target fuzz_texture_off
echo "fuzzer build: $((SECONDS - start)) s"
cd "$dir/fuzz"
rm -rf seeds && mkdir -p seeds corpus
find ../data/meshes -name '*.off' -size -4k -exec cp {} seeds \;
# A prism with flat star-shaped caps of eight corners, for step 1's triangulation in the plane.
printf 'OFF\n16 10 0\n0.5 0 0\n0.707 0.707 0\n0 0.5 0\n-0.707 0.707 0\n-0.5 0 0\n-0.707 -0.707 0\n0 -0.5 0\n0.707 -0.707 0\n0.5 0 1\n0.707 0.707 1\n0 0.5 1\n-0.707 0.707 1\n-0.5 0 1\n-0.707 -0.707 1\n0 -0.5 1\n0.707 -0.707 1\n8 7 6 5 4 3 2 1 0\n8 8 9 10 11 12 13 14 15\n4 0 1 9 8\n4 1 2 10 9\n4 2 3 11 10\n4 3 4 12 11\n4 4 5 13 12\n4 5 6 14 13\n4 6 7 15 14\n4 7 0 8 15\n' > seeds/star_prism.off
export ASAN_OPTIONS=detect_leaks=1
export UBSAN_OPTIONS=print_stacktrace=1
./fuzz_texture_off -max_total_time="${NP_FUZZ_SECONDS:-60}" -max_len=4096 -timeout=30 -rss_limit_mb=4096 \
                   -print_final_stats=1 corpus seeds
