#!/usr/bin/env bash
# ab.sh — A/B of two facet binaries on benchmark scenes, run alternately so that the machine's
# slow and fast spells fall on both: for each scene, ROUNDS runs of each binary (one frame count
# each), then the median of the runs' medians and the smallest of their minimums, in ms, and the
# median of the rounds' ratios (new median / old median).
#
# Usage: bench/ab.sh OLD_BINARY NEW_BINARY ROUNDS SCENE...
# Environment: THREADS (default 1), SIZE (default facet's 1920x1080), FRAMES (default 12).
set -euo pipefail
[ $# -ge 4 ] || { echo "usage: $0 OLD_BINARY NEW_BINARY ROUNDS SCENE..." >&2; exit 2; }
old=$1 new=$2 rounds=$3
shift 3
run() {  # run BINARY SCENE: prints "median min" of one bench run
  "$1" bench --threads "${THREADS:-1}" --frames "${FRAMES:-12}" --warmup 2 \
    ${SIZE:+--size "$SIZE"} --scene "$2" 2>/dev/null | awk 'NR == 2 { print $2, $3 }'
}
median() { printf '%s\n' "$@" | sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
smallest() { printf '%s\n' "$@" | sort -n | head -1; }
for scene in "$@"; do
  old_med=() old_min=() new_med=() new_min=()
  for _ in $(seq "$rounds"); do
    read -r med min < <(run "$old" "$scene"); old_med+=("$med"); old_min+=("$min")
    read -r med min < <(run "$new" "$scene"); new_med+=("$med"); new_min+=("$min")
  done
  # Each round's two runs are a minute apart at most: their ratio is the least disturbed by the
  # machine's slow spells, which can slow a whole run by half.
  ratios=()
  for i in "${!old_med[@]}"; do
    ratios+=("$(awk -v a="${old_med[$i]}" -v b="${new_med[$i]}" 'BEGIN { printf "%.4f", b / a }')")
  done
  echo "$scene  median: old=$(median "${old_med[@]}") new=$(median "${new_med[@]}")" \
    "  min: old=$(smallest "${old_min[@]}") new=$(smallest "${new_min[@]}")" \
    "  new/old: $(median "${ratios[@]}") (median of the rounds')"
done
