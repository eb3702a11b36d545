#!/usr/bin/env bash
# make bench: the many-risers load figure (bench/many_risers.sh), only with RISER_SIM_BENCH_MANY set (it takes
# 10-20 minutes per figure): 1 (or 2d) the paper's 500 m riser, 3d the 3D sea riser, all both.
set -eo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
case "${RISER_SIM_BENCH_MANY:-0}" in
  1|2d) spaces="2d" ;;
  3d) spaces="3d" ;;
  all) spaces="2d 3d" ;;
  *)
    echo "== Many risers: skipped; RISER_SIM_BENCH_MANY=1 (or 3d, all) make bench runs it (10-20 min per figure) =="
    exit 0 ;;
esac
for space in $spaces; do
  echo "== Many risers at real time ($space): nodes and nodelets =="
  "$root/bench/many_risers.sh" both 20 "$space"
done
