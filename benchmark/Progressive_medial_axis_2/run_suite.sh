#!/usr/bin/env bash
# The benchmark suite: fetches the data, builds the benchmark programs, runs
# them, and writes benchmark/Progressive_medial_axis_2/RESULTS.md and plots/.
#
#   benchmark/Progressive_medial_axis_2/run_suite.sh [--quick]
#
# --quick uses the "quick" set of data/shapes.tsv and shorter time limits (under
# 10 minutes on 2 cores); without it, the "full" set.  Needs the network once
# (npm registry) to fetch the country outlines.
set -euo pipefail
cd "$(dirname "$0")/../.."
here=benchmark/Progressive_medial_axis_2
quick=0
[ "${1:-}" = "--quick" ] && quick=1
if [ $quick = 1 ]; then
  set_name=quick; runs=3; timeout=300; exact_timeout=20
else
  set_name=full; runs=3; timeout=1200; exact_timeout=60
fi

scripts/install_deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPMA_BUILD_BENCHMARKS=ON > build-configure.log
cmake --build build -j2 --target bench_time bench_accuracy make_synthetic make_degenerate progressive_medial_axis

if [ $quick = 1 ]; then python3 $here/fetch_data.py --quick; else python3 $here/fetch_data.py; fi
# the shapes of the set that validated: columns name file kind vertices holes sets source status
files=$(awk -F'\t' -v s="$set_name" 'NR > 1 && $6 ~ s && $8 == "ok" { print $2 }' $here/data/shapes.tsv)

results=$here/results
rm -rf $results/nv $results/accuracy
mkdir -p $results/nv $results/accuracy
{
  echo "date: $(date -u +%Y-%m-%dT%H:%MZ)"
  lscpu | grep -E "^(Model name|CPU\(s\)|Thread|Core|Socket)" || true
  echo "memory: $(free -g | awk '/Mem:/ { print $2 " GiB" }')"
  echo "os: $(. /etc/os-release; echo "$PRETTY_NAME"), kernel $(uname -r)"
  echo "compiler: $(g++ --version | head -1)"
  echo "CGAL: $(dpkg-query -W -f='${Version}' libcgal-dev), Boost: $(dpkg-query -W -f='${Version}' libboost-dev), build type Release"
  echo "load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
} > $results/machine.txt

bench_time="build/benchmark/Progressive_medial_axis_2/bench_time --runs $runs --timeout $timeout --exact-timeout $exact_timeout --nv-dump $results/nv"
bench_accuracy="build/benchmark/Progressive_medial_axis_2/bench_accuracy --timeout $timeout --exact-timeout $exact_timeout --dump $results/accuracy"
{
  echo "$here/run_suite.sh $*"
  echo "$bench_time FILES > $results/time.tsv"
  echo "$bench_accuracy FILES > $results/accuracy.tsv"
  echo "python3 $here/make_report.py $results"
  echo "FILES: the '$set_name' set of $here/data/shapes.tsv:"
  echo "$files" | sed 's/^/  /'
} > $results/commands.txt

$bench_time $files > $results/time.tsv
$bench_accuracy $files > $results/accuracy.tsv
python3 $here/make_report.py $results
