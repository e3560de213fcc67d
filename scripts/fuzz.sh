#!/usr/bin/env bash
# Builds the libFuzzer target on the scene loader with clang-14 and runs it for N seconds
# (default 60) from the seed corpus. A crash leaves its input in build-fuzz/ and fails.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
# Only the fuzz target is built: the rest of the tree is built and tested with gcc already.
cmake -S "$root" -B "$root/build-fuzz" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_COMPILER=clang++-14 -DRAINTRACE_FUZZ=ON \
  -DRAINTRACE_BUILD_TESTS=OFF -DRAINTRACE_BUILD_BENCH=OFF > /dev/null
cmake --build "$root/build-fuzz" --target fuzz_scene
corpus=$root/build-fuzz/corpus
mkdir -p "$corpus"
cp "$root"/fuzz/corpus/* "$root"/examples/*.toml "$corpus"/ 2>/dev/null || true
cd "$root/build-fuzz"
./fuzz/fuzz_scene -dict="$root/fuzz/scene.dict" -max_total_time="$seconds" -print_final_stats=1 \
  "$corpus" 2>&1 | tail -5
