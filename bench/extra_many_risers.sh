#!/usr/bin/env bash
# make bench: the many-risers load figure (bench/many_risers.sh), only with RISER_SIM_BENCH_MANY=1 (it
# takes 10-20 minutes).
set -eo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if [ "${RISER_SIM_BENCH_MANY:-0}" != 1 ]; then
  echo "== Many risers: skipped; RISER_SIM_BENCH_MANY=1 make bench runs it (10-20 min) =="
  exit 0
fi
echo "== Many risers at real time: nodes and nodelets =="
"$root/bench/many_risers.sh" both
