#!/usr/bin/env bash
# vs_gl.sh — facet against its OpenGL twin (docs/gl_twin.md) on the scenes the twin can draw, in
# the same session: `facet bench --backend gl` and `facet bench --backend facet` one right after
# the other, ROUNDS times; then per scene each backend's median over the rounds and the ratio
# (OpenGL ms / facet ms: above 1 means facet is faster). Without a GPU that OpenGL is Mesa's
# llvmpipe (the first line says which); both at SIZE with THREADS threads, without MSAA.
# READBACK off times the twin's frames as glmark2 times llvmpipe's: into an 8-bit sRGB target,
# clear, draw, glFinish, no readback (facet bench --gl-readback off): llvmpipe drawing the view.
#
# Usage: bench/vs_gl.sh [ROUNDS] [THREADS] [SIZE] [READBACK]
#        (default 5 rounds, 2 threads, 1920x1080, readback on)
set -euo pipefail
cd "$(dirname "$0")/.."
ROUNDS=${1:-5}
THREADS=${2:-2}
SIZE=${3:-1920x1080}
READBACK=${4:-on}
[ -x build/facet ] || { echo "build facet first (make build)" >&2; exit 2; }
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
date -u
for r in $(seq "$ROUNDS"); do
  build/facet bench --backend gl --gl-readback "$READBACK" --threads "$THREADS" --size "$SIZE" \
    --frames 20 >"$OUT/gl.txt"
  [ "$r" -gt 1 ] || head -1 "$OUT/gl.txt"
  awk -v r="$r" '$2 ~ /^[0-9.]+$/ { print $1, r, $2 }' "$OUT/gl.txt" >>"$OUT/gl"
  scenes=$(awk '$2 ~ /^[0-9.]+$/ { printf "%s%s", sep, $1; sep = "," }' "$OUT/gl.txt")
  build/facet bench --backend facet --scene "$scenes" --threads "$THREADS" --size "$SIZE" \
    --frames 20 | awk -v r="$r" '$2 ~ /^[0-9.]+$/ { print $1, r, $2 }' >>"$OUT/facet"
done
date -u
source bench/round_medians.sh
medians "$OUT/facet" >"$OUT/facet.med"
medians "$OUT/gl" >"$OUT/gl.med"
echo "scene | facet ms | OpenGL ms | ratio | facet rounds | OpenGL rounds"
join "$OUT/facet.med" "$OUT/gl.med" | awk -v n="$ROUNDS" '{
  rounds_f = ""; for (i = 3; i < 3 + n; i++) rounds_f = rounds_f " " $i
  gl = $(3 + n); rounds_g = ""; for (i = 4 + n; i <= NF; i++) rounds_g = rounds_g " " $i
  printf "%s | %.2f | %.2f | %.2fx |%s |%s\n", $1, $2, gl, gl / $2, rounds_f, rounds_g
}'
