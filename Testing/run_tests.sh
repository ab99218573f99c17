#!/usr/bin/env bash
# Set up and build, then run every test (ctest under a virtual X server for the image tests).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/Examples/setup.sh"
cd "$here/build"
xvfb-run -a ctest --output-on-failure "$@"
