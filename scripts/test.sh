#!/usr/bin/env bash
# The README's second command (and CI's): installs what is missing, builds, and runs the whole
# test suite: unit + POV-Ray + Slurm + browser tests, again under ASan+UBSan (but for the
# full-scale examples), a bounded libFuzzer run on the scene loader, and the clang-format check.
# Usage: scripts/test.sh [--quick]   (--quick: only the normal build's ctest run)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
quick=false; [[ ${1:-} == --quick ]] && quick=true
jobs=$(nproc)
step() { printf '\n== %s (%s)\n' "$1" "$(date -u +%H:%M:%S)"; }

step "dependencies"
"$root/scripts/install-deps.sh" --test

# Both builds compile each target's sources in unity batches (CMake's CMAKE_UNITY_BUILD, 8 files
# a batch): the headers they share (gtest, fmt, OpenImageIO, CLI11) are parsed once a batch
# instead of once a file. A fresh build took 349 s instead of 600 (607 against 1097 CPU s). So
# names in anonymous namespaces must differ within a target; scripts/build.sh alone still
# compiles file by file, which is what shows a missing #include.
unity=-DCMAKE_UNITY_BUILD=ON

step "build (warnings are errors)"
"$root/scripts/build.sh" "$root/build" -DRAINTRACE_WERROR=ON "$unity"

step "tests"
(cd "$root/build" && ctest --output-on-failure -j "$jobs" --timeout 900)
$quick && exit 0

step "clang-format"
command -v clang-format >/dev/null || { echo "clang-format missing (scripts/install-deps.sh --test)"; exit 1; }
unformatted=$(cd "$root" && git ls-files '*.cpp' '*.h' | xargs -r clang-format --dry-run 2>&1 | grep -c warning || true)
if [[ $unformatted != 0 ]]; then
  (cd "$root" && git ls-files '*.cpp' '*.h' | xargs -r clang-format --dry-run 2>&1 | grep warning | head -20)
  echo "clang-format: files above need formatting (clang-format -i)"; exit 1
fi

step "sanitized build (ASan + UBSan)"
# -O1 -g1 instead of the build type's -O2 -g: half the compile time under the sanitizers (1434
# against 2792 CPU s for the whole build), the same test run time, and the line tables the
# sanitizers' stack traces need. Here, not in the option: a sanitized Debug build keeps its -g.
"$root/scripts/build.sh" "$root/build-asan" -DRAINTRACE_SANITIZE=ON -DRAINTRACE_BUILD_BENCH=OFF \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" "$unity"
step "sanitized tests"
# All but the suites that run whole examples at a user's size (the documents' commands and the
# examples' figures): under ASan they took 2070 of the 3270 test-seconds in a fresh-clone run,
# and the small tests take the sanitizers through the same code.
full_scale='^(DocExamples|SlurmDocExamples|ExampleFigures)\.'
(cd "$root/build-asan" && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  LSAN_OPTIONS=suppressions="$root/cmake/lsan.supp" \
  ctest --output-on-failure -j "$jobs" --timeout 1800 -E "$full_scale")

step "fuzzing the scene loader (60 s)"
"$root/scripts/fuzz.sh" 60
