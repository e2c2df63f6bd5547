#!/usr/bin/env bash
# thumbnails_batch_vs_f3d.sh — a folder's worth of thumbnails: 100 thumbnails (256x256 PNGs) of
# the model files of Debian's assimp-testmodels and glmark2-data that both programs read (OBJ,
# PLY, STL, glTF, 3DS; those facet renders, about 85, in name order, the first ones again to
# make 100). facet does them in one command (`facet render FILES... -o DIR/`); f3d
# (Debian package f3d, VTK on Mesa llvmpipe) is started once per file, as a file manager's
# thumbnailer would start it. Rounds alternate the two; prints each round's wall time and the
# medians.
#
# Usage: bench/thumbnails_batch_vs_f3d.sh [ROUNDS]    (default 3)
# Needs: a built facet (build/facet), f3d, xvfb and assimp-testmodels.
set -euo pipefail
cd "$(dirname "$0")/.."
ROUNDS=${1:-3}
FACET=build/facet
MODELS=/usr/share/assimp/models
OUT=$(mktemp -d)
XVFB_PID=""  # set once Xvfb runs: the checks before it may exit first
trap '[ -n "$XVFB_PID" ] && kill "$XVFB_PID" 2>/dev/null; rm -rf "$OUT"' EXIT
command -v f3d >/dev/null || { echo "f3d is not installed (apt-get install f3d)" >&2; exit 2; }
command -v Xvfb >/dev/null || { echo "Xvfb is not installed (apt-get install xvfb)" >&2; exit 2; }
[ -d "$MODELS" ] || { echo "assimp-testmodels is not installed" >&2; exit 2; }
[ -x "$FACET" ] || { echo "build facet first (make build)" >&2; exit 2; }

# The files: valid samples only (no invalid/ folders), those facet renders on its own.
mapfile -t candidates < <(find "$MODELS"/{OBJ,PLY,STL,glTF2,3DS} /usr/share/glmark2/models -type f \
  \( -iname '*.obj' -o -iname '*.ply' -o -iname '*.stl' -o -iname '*.glb' -o -iname '*.gltf' \
     -o -iname '*.3ds' \) -not -path '*nvalid*' | LC_ALL=C sort)
models=()
for f in "${candidates[@]}"; do
  "$FACET" render "$f" --size 256x256 -o "$OUT/probe.png" -q >/dev/null 2>&1 && models+=("$f")
done
files=()
while [ ${#files[@]} -lt 100 ]; do files+=("${models[@]:0:$((100 - ${#files[@]}))}"); done
echo "${#files[@]} thumbnails of ${#models[@]} models, 256x256 PNGs, $ROUNDS rounds alternated"

DISPLAY_NUMBER=96
Xvfb :$DISPLAY_NUMBER -screen 0 1920x1080x24 >/dev/null 2>&1 &
XVFB_PID=$!
sleep 1

millis() { echo $(( $(date +%s%N) / 1000000 )); }
median() { sort -n | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }

facet_batch() {
  rm -rf "$OUT/facet" && mkdir -p "$OUT/facet"
  "$FACET" render "${files[@]}" --size 256x256 -o "$OUT/facet/" -q >/dev/null 2>&1 || true
}
f3d_each() {
  rm -rf "$OUT/f3d" && mkdir -p "$OUT/f3d"
  local i=0
  for f in "${files[@]}"; do
    DISPLAY=:$DISPLAY_NUMBER f3d --resolution=256,256 --output="$OUT/f3d/$i.png" "$f" \
      >/dev/null 2>&1 || true
    i=$((i + 1))
  done
}

facet_times="" f3d_times=""
for _ in $(seq "$ROUNDS"); do
  start=$(millis); facet_batch; facet_times+="$(( $(millis) - start )) "
  start=$(millis); f3d_each; f3d_times+="$(( $(millis) - start )) "
done
echo "facet ms: $facet_times($(ls "$OUT/facet" | wc -l) images)"
echo "f3d   ms: $f3d_times($(ls "$OUT/f3d" | wc -l) images)"
fm=$(echo "$facet_times" | tr ' ' '\n' | grep . | median)
dm=$(echo "$f3d_times" | tr ' ' '\n' | grep . | median)
echo "median facet ${fm} ms, f3d ${dm} ms, f3d/facet $(awk -v a="$dm" -v b="$fm" 'BEGIN { printf "%.1f", a / b }')x"
