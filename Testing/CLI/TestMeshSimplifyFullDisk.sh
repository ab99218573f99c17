#!/usr/bin/env bash
# meshsimplify on a full disk: a 48 KiB tmpfs mounted in a mount namespace of the test's own.
# For every output format the run must exit with status 1 and one line "meshsimplify: cannot
# write '<file>': <reason>", leave no file (no partial output, no temporary file), and leave an
# existing file of the same name untouched. Before, .vtp crashed in VTK's writer, .ply and .obj
# exited 0 with a truncated file and .off left its partial file. Exits 77 (skipped) where no
# mount namespace can be made (not root, or a container that forbids it).
#
#   TestMeshSimplifyFullDisk.sh <meshsimplify> <input mesh> <work directory>
set -u
tool=$1 input=$2 work=$3
if [ "${4:-}" != inside ]; then
  unshare -m true 2>/dev/null || { echo "no mount namespace here: skipped"; exit 77; }
  exec unshare -m bash "$0" "$tool" "$input" "$work" inside
fi
disk="$work/full_disk"
mkdir -p "$disk"
mount -t tmpfs -o size=48k tmpfs "$disk" || { echo "cannot mount a tmpfs: skipped"; exit 77; }
failures=0
fail() { echo "check failed: $*"; failures=$((failures + 1)); }
for extension in vtp ply stl obj off vtk; do
  echo keep >"$disk/existing.$extension"
  for name in "new.$extension" "existing.$extension"; do
    errors=$("$tool" --method parallel --reduction 0.1 "$input" "$disk/$name" 2>&1 >/dev/null)
    status=$?
    lines=$(printf '%s\n' "$errors" | wc -l)
    [ $status -eq 1 ] || fail "$name: exit $status"
    [ "$lines" -eq 1 ] && [[ $errors == "meshsimplify: cannot write '$disk/$name': "* ]] ||
      fail "$name: $errors"
  done
  [ ! -e "$disk/new.$extension" ] || fail "new.$extension: a partial file is left"
  [ "$(cat "$disk/existing.$extension")" = keep ] || fail "existing.$extension was changed"
done
leftovers=$(ls -A "$disk" | grep -v '^existing\.' || true)
[ -z "$leftovers" ] || fail "files left on the disk: $leftovers"
umount "$disk"
echo "$failures failed"
[ $failures -eq 0 ]
