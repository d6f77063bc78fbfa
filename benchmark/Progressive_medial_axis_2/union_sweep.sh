#!/usr/bin/env bash
# The tool's --union against a one-shot of the union polygon (which the
# oracle tests check against SDG), on pairs PREFIX_a.wkt / PREFIX_b.wkt
# (union_splits.py writes them).  Prints one line per pair: "same" or
# "DIFFERENT" (the files PREFIX_cmp.txt say how), and the --stats keys
# anomalies, undecided_ties, union_shared_edges, union_chains and
# union_recomputed.  Usage, from a build with tests:
#   benchmark/Progressive_medial_axis_2/union_sweep.sh PREFIX...
set -uo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
T=$root/build/tool/Progressive_medial_axis_2/progressive_medial_axis
C=$root/build/test/Progressive_medial_axis_2/compare_pairs
for p in "$@"; do
  a=${p}_a.wkt; b=${p}_b.wkt
  # (one run: its pair lines start with "pair", the --stats lines do not)
  if ! $T --pairs --stats --union "$b" --shape-out "${p}_u.wkt" "$a" > "${p}_out.txt" 2> "${p}_err.txt"; then
    echo "$p UNION-FAILED $(head -c 300 "${p}_err.txt")"; continue
  fi
  grep '^pair ' "${p}_out.txt" > "${p}_up.txt"
  st=$(awk '$1=="anomalies"||$1=="undecided_ties"||$1=="union_shared_edges"||$1=="union_chains"||$1=="union_recomputed"{printf "%s=%s ", $1, $2}' "${p}_out.txt")
  $T --pairs "${p}_u.wkt" > "${p}_op.txt" 2>> "${p}_err.txt"
  if $C "${p}_u.wkt" "${p}_up.txt" "${p}_op.txt" > "${p}_cmp.txt" 2>&1; then r=same; else r=DIFFERENT; fi
  echo "$p $r $st$([ -s "${p}_err.txt" ] && echo " stderr: $(head -c 200 "${p}_err.txt")")"
done
