#!/usr/bin/env bash
# Builds the package and runs its main job: a progressive medial axis of a
# shape shipped with the project, drawn at several steps, by region growing
# and by boundary evolution.
# Pictures and data go to out/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > build-configure.log
cmake --build build -j2 --target progressive_medial_axis
mkdir -p out
shape=examples/Progressive_medial_axis_2/data/maze20.wkt
build/tool/Progressive_medial_axis_2/progressive_medial_axis --stats \
  --frames 8 --frames-prefix out/maze20_step --html out/maze20_viewer.html \
  --svg out/maze20_axis.svg --geojson out/maze20_axis.geojson --wkt-out out/maze20_axis.wkt \
  "$shape"
build/tool/Progressive_medial_axis_2/progressive_medial_axis --progressive boundary \
  --frames 8 --frames-prefix out/maze20_boundary_step --html out/maze20_boundary_viewer.html "$shape"
echo "pictures: out/maze20_step_000.svg ... out/maze20_step_007.svg (region growing), out/maze20_axis.svg (final)"
echo "          out/maze20_boundary_step_000.svg ... _007.svg (boundary evolution)"
echo "viewers: out/maze20_viewer.html, out/maze20_boundary_viewer.html (open them in a browser: a slider over the steps, pan and zoom)"
