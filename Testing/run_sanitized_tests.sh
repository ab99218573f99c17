#!/usr/bin/env bash
# The core's unit tests, the command-line tool's tests (damaged files, a full disk) and the two
# fuzz targets, built a second time with AddressSanitizer and UndefinedBehaviorSanitizer into
# build-sanitize/ (as meshoptimizer's CI runs its sanitizer build): any finding fails the test
# that made it. Needs what Examples/setup.sh installs.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cmake -S "$here" -B "$here/build-sanitize" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBUILD_TESTING=ON \
  -DMESHSIMPLIFICATION_SANITIZE=ON -DMESHSIMPLIFICATION_FUZZ_RUNS=4000 >/dev/null
cmake --build "$here/build-sanitize" -j "$(nproc)" --target CoreTests meshsimplify TestMeshSimplifyBadFiles \
  FuzzCore FuzzMeshFiles
cd "$here/build-sanitize"
export ASAN_OPTIONS="abort_on_error=1:detect_leaks=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
ctest --output-on-failure -R '^(Core|CLI|Fuzz)\.' "$@"
