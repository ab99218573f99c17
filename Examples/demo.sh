#!/usr/bin/env bash
# The main job: set up and build, then simplify the bundled cow and terrain and write the
# simplified meshes and before/after pictures to Examples/output/.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/Examples/setup.sh"
mkdir -p "$here/Examples/output"
xvfb-run -a pvbatch --force-offscreen-rendering "$here/Examples/demo.py" \
  --plugin "$(find "$here/build/lib" -name MeshSimplification.so | head -n 1)" \
  --data "$here/Testing/Data" --output "$here/Examples/output"
echo "Results in $here/Examples/output"
