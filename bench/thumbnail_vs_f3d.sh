#!/usr/bin/env bash
# thumbnail_vs_f3d.sh — the thumbnailer job, end to end: load a model, render it at 1920x1080
# and write a PNG; facet against f3d (Debian package f3d, VTK on Mesa llvmpipe) on the same
# file in the same session. Prints per-run wall times and the medians in milliseconds.
#
# Usage: bench/thumbnail_vs_f3d.sh [MODEL] [RUNS]    (default: glmark2's bunny.obj, 7 runs)
# Needs: a built facet (build/facet), f3d and xvfb (f3d needs an X display; one Xvfb is
# started for all its runs so the server start-up is not counted).
set -euo pipefail
cd "$(dirname "$0")/.."
MODEL=${1:-/usr/share/glmark2/models/bunny.obj}
RUNS=${2:-7}
FACET=build/facet
OUT=$(mktemp -d)
XVFB_PID=""  # set once Xvfb runs: the checks before it may exit first
trap '[ -n "$XVFB_PID" ] && kill "$XVFB_PID" 2>/dev/null; rm -rf "$OUT"' EXIT
command -v f3d >/dev/null || { echo "f3d is not installed (apt-get install f3d)" >&2; exit 2; }
command -v Xvfb >/dev/null || { echo "Xvfb is not installed (apt-get install xvfb)" >&2; exit 2; }
[ -x "$FACET" ] || { echo "build facet first (make build)" >&2; exit 2; }

DISPLAY_NUMBER=97
Xvfb :$DISPLAY_NUMBER -screen 0 1920x1080x24 >/dev/null 2>&1 &
XVFB_PID=$!
sleep 1

millis() { echo $(( $(date +%s%N) / 1000000 )); }
median() { sort -n | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }

wall_ms() {  # command... ; prints its wall time
  local start end
  start=$(millis)
  "$@" >/dev/null 2>&1
  end=$(millis)
  echo $((end - start))
}

# Alternated (facet, f3d, facet, ...), so a noisy spell of the shared machine hits both.
echo "model: $MODEL, $RUNS runs each, alternated, 1920x1080 PNG"
facet_times="" f3d_times=""
for _ in $(seq "$RUNS"); do
  facet_times+="$(wall_ms "$FACET" render "$MODEL" --size 1920x1080 -o "$OUT/facet.png") "
  f3d_times+="$(DISPLAY=:$DISPLAY_NUMBER wall_ms f3d --resolution=1920,1080 --output="$OUT/f3d.png" "$MODEL") "
done
echo "facet ms: $facet_times"
echo "f3d   ms: $f3d_times"
fm=$(echo "$facet_times" | tr ' ' '\n' | grep . | median)
dm=$(echo "$f3d_times" | tr ' ' '\n' | grep . | median)
echo "median facet ${fm} ms, f3d ${dm} ms, f3d/facet $(awk -v a="$dm" -v b="$fm" 'BEGIN { printf "%.1f", a / b }')x"
