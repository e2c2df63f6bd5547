#!/usr/bin/env bash
# dask_throughput.sh — views per second of examples/python/dask_dataset.py (facet.dask) on this
# machine: ROUNDS rounds, each running every set-up once into a fresh folder, one after the
# other; then each set-up's median and its runs. The time is the job's alone (facet.dask.render
# or render_local), without starting the cluster or loading the model on the driver.
#
# Usage: bench/dask_throughput.sh [MODEL] [VIEWS] [ROUNDS]
#   (defaults: /usr/share/glmark2/models/bunny.obj, 100, 3; 640x480, color and depth)
# Environment: PYTHON (default /usr/bin/python3); PYTHONPATH (default build/python/package);
# TMPDIR, where the output folders are made (default /tmp; /dev/shm leaves the disk out).
set -euo pipefail
model=${1:-/usr/share/glmark2/models/bunny.obj} views=${2:-100} rounds=${3:-3}
export PYTHONPATH=${PYTHONPATH:-build/python/package}
setups=("--local" "--workers 1" "--workers 2" "--workers 1 --threads-per-worker 2")
declare -A runs
for _ in $(seq "$rounds"); do
  for setup in "${setups[@]}"; do
    out=$(mktemp -d)
    # shellcheck disable=SC2086  # the set-up is several arguments
    rate=$("${PYTHON:-/usr/bin/python3}" examples/python/dask_dataset.py "$model" "$out" \
             --views "$views" --size 640x480 --quiet $setup |
           grep -o '[0-9.]* views/s$' | cut -d' ' -f1)
    rm -rf "$out"
    runs[$setup]="${runs[$setup]:-} $rate"
  done
done
median() { printf '%s\n' "$@" | sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
printf '%-40s %8s   %s\n' "set-up" "median" "runs (views/s)"
for setup in "${setups[@]}"; do
  # shellcheck disable=SC2086
  printf '%-40s %8s   %s\n' "$setup" "$(median ${runs[$setup]})" "${runs[$setup]# }"
done
