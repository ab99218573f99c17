#!/usr/bin/env bash
# Set up and build, then run every test (ctest under a virtual X server for the image tests),
# then the core, command-line and fuzz tests again in a sanitizer build (run_sanitized_tests.sh).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/Examples/setup.sh"
cd "$here/build"
# -noreset: the server does not reset when its last client leaves, which under load let the
# next test's first connection fail ("bad X server connection").
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" ctest --output-on-failure "$@"
"$here/Testing/run_sanitized_tests.sh"
