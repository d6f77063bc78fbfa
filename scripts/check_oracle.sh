#!/usr/bin/env bash
# Compares the tool's --pairs with the oracle program sdg_pairs on polygon
# files, for the full shape (the plain run, and for region growing also its
# last step) and at several --step values (fractions of the step count).  Usage: scripts/check_oracle.sh [--traits T] [--progressive D] FILE.wkt...
# (--progressive boundary: the steps, and the full run, of boundary evolution)
# Needs a build with tests (scripts/test.sh, or cmake --build build).
set -uo pipefail
cd "$(dirname "$0")/.."
traits=filtered
driver=region
while [ $# -gt 0 ]; do
  case "$1" in
    --traits) traits=$2; shift 2 ;;
    --progressive) driver=$2; shift 2 ;;
    *) break ;;
  esac
done
tool=build/tool/Progressive_medial_axis_2/progressive_medial_axis
oracle=build/test/Progressive_medial_axis_2/sdg_pairs
compare=build/test/Progressive_medial_axis_2/compare_pairs
tmp=$(mktemp -d)
status=0
for f in "$@"; do
  steps=$($tool --stats --step 0 --progressive $driver "$f" | awk '$1=="steps"{print $2}')
  # (the steps strictly between the first and the last, each once: a shape
  # of 0 or 1 steps has only its full run)
  ks=$(for k in 1 10 $((steps/10)) $((steps/3)) $((2*steps/3)) $((steps-1)); do
         [ "$k" -ge 1 ] && [ "$k" -lt "$steps" ] && echo "$k"; done | sort -nu)
  # (full: the tool's plain run, which for region is the one-shot; last:
  # the driver's own last step, the axis of the whole shape again)
  last=""; [ $driver = region ] && [ "$steps" -ge 1 ] && last=last
  for k in full $last $ks; do
    if [ "$k" = full ]; then
      progressive=""; [ $driver = region ] || progressive="--progressive $driver"
      $tool --traits $traits --pairs $progressive "$f" > $tmp/ours.txt; shape=$f
    elif [ "$k" = last ]; then
      $tool --traits $traits --pairs --progressive $driver "$f" > $tmp/ours.txt; shape=$f
    else
      $tool --traits $traits --pairs --progressive $driver --step $k --shape-out $tmp/shape.wkt "$f" > $tmp/ours.txt; shape=$tmp/shape.wkt
    fi
    $oracle "$shape" > $tmp/oracle.txt
    result=$($compare "$shape" $tmp/ours.txt $tmp/oracle.txt) || status=1
    printf '%s\tstep %s of %s\t%s\n' "$(basename "$f")" "$k" "$steps" "$(echo "$result" | head -1)"
    [ "$(echo "$result" | head -1 | grep -c DIFFER)" = 0 ] || echo "$result" | tail -n +2 | head -20
  done
done
rm -rf $tmp
exit $status
