#!/usr/bin/env bash
# 3D sea speed/accuracy sweep (bench/sea3d_sweep.py): ~1 min.
set -eo pipefail
echo "== 3D sea: speed vs accuracy =="
"$(cd "$(dirname "$0")" && pwd)/sea3d_sweep.py"
