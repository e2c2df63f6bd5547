#!/usr/bin/env bash
# dataset_vs_vtk.sh — the dataset job of issue 28: a model from 100 viewpoints on a sphere, color
# PNG + depth .npy at 640x480, with facet's Python module (examples/python/dataset.py) and with
# VTK's Python offscreen rendering on Mesa llvmpipe (bench/dataset_vtk.py, Debian python3-vtk9,
# under one Xvfb), alternated in the same session. Prints each run's seconds for the views
# (model loading and process start-up not counted, for either) and the medians.
#
# Usage: bench/dataset_vs_vtk.sh [MODEL] [RUNS]    (default: glmark2's bunny.obj, 3 runs)
# Needs: a built facet with its Python module (make build), python3-vtk9, xvfb.
set -euo pipefail
cd "$(dirname "$0")/.."
MODEL=${1:-/usr/share/glmark2/models/bunny.obj}
RUNS=${2:-3}
PYTHON=/usr/bin/python3
OUT=$(mktemp -d)
XVFB_PID=""  # set once Xvfb runs: the checks before it may exit first
trap '[ -n "$XVFB_PID" ] && kill "$XVFB_PID" 2>/dev/null; rm -rf "$OUT"' EXIT
"$PYTHON" -c "import vtk" 2>/dev/null || { echo "install python3-vtk9" >&2; exit 2; }
[ -d build/python/package/facet ] || { echo "build facet first (make build)" >&2; exit 2; }

DISPLAY_NUMBER=96
Xvfb :$DISPLAY_NUMBER -screen 0 1280x1024x24 >/dev/null 2>&1 &
XVFB_PID=$!
sleep 1

median() { sort -n | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }

facet_times="" vtk_times=""
for run in $(seq "$RUNS"); do
  rm -rf "$OUT"/*
  f=$(PYTHONPATH=build/python/package "$PYTHON" examples/python/dataset.py "$MODEL" "$OUT/facet" \
        --views 100 --size 640x480 --outputs color,depth | sed -n 's/.*, \([0-9.]*\) s$/\1/p')
  v=$(DISPLAY=:$DISPLAY_NUMBER LIBGL_ALWAYS_SOFTWARE=1 "$PYTHON" bench/dataset_vtk.py "$MODEL" \
        "$OUT/vtk" --views 100 --size 640x480)
  echo "run $run: facet $f s, vtk $v s"
  facet_times+="$f"$'\n' vtk_times+="$v"$'\n'
done
fm=$(printf '%s' "$facet_times" | median)
vm=$(printf '%s' "$vtk_times" | median)
echo "medians: facet $fm s, vtk (llvmpipe) $vm s: facet $(awk -v f="$fm" -v v="$vm" 'BEGIN { printf "%.1f", v / f }')x faster"
