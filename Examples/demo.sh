#!/usr/bin/env bash
# The main job: set up and build, then simplify the bundled cow and terrain and write the
# simplified meshes and before/after pictures to Examples/output/.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/Examples/setup.sh"
mkdir -p "$here/Examples/output"
# -noreset: the server does not reset when a client leaves, which can refuse the next connection.
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" pvbatch --force-offscreen-rendering "$here/Examples/demo.py" \
  --plugin "$(find "$here/build/lib" -name MeshSimplification.so | head -n 1)" \
  --data "$here/Testing/Data" --output "$here/Examples/output"
echo "Results in $here/Examples/output"
