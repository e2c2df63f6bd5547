#!/usr/bin/env bash
# vs_llvmpipe.sh — facet against Mesa llvmpipe on the glmark2 scenes, in the same session:
# ../shared/bench/peer-llvmpipe.sh (glmark2 on llvmpipe) and `facet bench`, one right after the
# other, ROUNDS times; then per scene each renderer's median over the rounds, the ratio
# (llvmpipe ms / facet ms: above 1 means facet is faster) and every round's value, and facet's
# own scenes' medians. Both at 1920x1080 with THREADS threads.
#
# Usage: bench/vs_llvmpipe.sh [ROUNDS] [THREADS]    (default 5 rounds, 2 threads)
set -euo pipefail
cd "$(dirname "$0")/.."
ROUNDS=${1:-5}
THREADS=${2:-2}
PEER=../shared/bench/peer-llvmpipe.sh
[ -x build/facet ] || { echo "build facet first (make build)" >&2; exit 2; }
[ -e "$PEER" ] || { echo "$PEER not found" >&2; exit 2; }
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
date -u
for r in $(seq "$ROUNDS"); do
  bash "$PEER" --threads "$THREADS" --duration 3 2>/dev/null |
    awk -F'\t' -v r="$r" 'NF == 4 { key = ($2 == "-") ? $1 : $1 ":" $2; print key, r, $4 }' \
      >>"$OUT/llvmpipe"
  build/facet bench --threads "$THREADS" --frames 20 2>/dev/null |
    awk -v r="$r" 'NR > 1 && $2 ~ /^[0-9.]+$/ { print $1, r, $2 }' >>"$OUT/facet"
done
date -u
source bench/round_medians.sh
medians "$OUT/llvmpipe" >"$OUT/llvmpipe.med"
medians "$OUT/facet" >"$OUT/facet.med"
echo "scene | facet ms | llvmpipe ms | ratio | facet rounds | llvmpipe rounds"
join -a 1 "$OUT/facet.med" "$OUT/llvmpipe.med" | awk '{
  facet = $2; rounds_f = ""; for (i = 3; i < 3 + '"$ROUNDS"'; i++) rounds_f = rounds_f " " $i
  if (NF > 2 + '"$ROUNDS"') {
    llvm = $(3 + '"$ROUNDS"'); rounds_l = ""
    for (i = 4 + '"$ROUNDS"'; i <= NF; i++) rounds_l = rounds_l " " $i
    printf "%s | %.1f | %.1f | %.2fx |%s |%s\n", $1, facet, llvm, llvm / facet, rounds_f, rounds_l
  } else {
    printf "%s | %.1f | - | - |%s |\n", $1, facet, rounds_f
  }
}'
# glmark2 scenes facet does not reproduce yet.
join -v 2 "$OUT/facet.med" "$OUT/llvmpipe.med" | awk '{ printf "%s | - | %.1f | - | |\n", $1, $2 }'
