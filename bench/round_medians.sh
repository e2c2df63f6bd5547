# Sourced by the scripts that alternate two renderers (vs_llvmpipe.sh, vs_gl.sh).
# medians FILE: FILE has lines "SCENE ROUND MS"; prints per scene, scenes sorted,
# "SCENE MEDIAN MS1 MS2 ..." (the median of its rounds, then every round's value, sorted).
medians() { sort -k1,1 -k3,3n "$1" | awk '
  { v[$1] = v[$1] " " $3; n[$1]++; all[$1, n[$1]] = $3 }
  END { for (k in n) print k, all[k, int((n[k] + 1) / 2)], v[k] }' | sort; }
