#!/usr/bin/env bash
# Two Ray nodes on this machine against the local pool with 2 workers, alternately:
# objects/s (wall clock of the whole command) of
#   artipg generate CATEGORY -n N --engine ray --address 127.0.0.1:6380
#   artipg generate CATEGORY -n N --workers 2
# Run it inside a network namespace that has only loopback (Ray's servers listen on
# every interface):  sudo unshare -n bash benchmarks/bench_ray_two_nodes.sh [N] [CATEGORY] [REPEATS]
set -euo pipefail
N=${1:-200}; CAT=${2:-storage_furniture}; REPEATS=${3:-2}
ip link set lo up 2>/dev/null || true
export PYTHONPATH="$(cd "$(dirname "$0")/.." && pwd)/src${PYTHONPATH:+:$PYTHONPATH}"
export RAY_USAGE_STATS_ENABLED=0 RAY_AUTH_MODE=${RAY_AUTH_MODE:-token}
OUT=$(mktemp -d)
trap 'ray stop >/dev/null 2>&1 || true; rm -rf "$OUT"' EXIT
ray start --head --port=6380 --num-cpus=1 --node-ip-address=127.0.0.1 --include-dashboard=false >/dev/null
ray start --address=127.0.0.1:6380 --num-cpus=1 --node-ip-address=127.0.0.1 >/dev/null
sleep 3
ray status --address=127.0.0.1:6380 | sed -n '/Active:/,/Pending:/p'
run() {  # name, extra args...
  local name=$1; shift
  rm -rf "$OUT/$name"
  local t0 t1; t0=$(date +%s.%N)
  python -m artipg.cli generate "$CAT" -n "$N" -q --out "$OUT/$name" "$@" >/dev/null
  t1=$(date +%s.%N)
  python -c "import sys; n,a,b=int(sys.argv[1]),float(sys.argv[2]),float(sys.argv[3]); print(f'{sys.argv[4]:>14}: {n/(b-a):6.1f} objects/s ({b-a:.1f} s)')" "$N" "$t0" "$t1" "$name"
}
for _ in $(seq "$REPEATS"); do
  run local-2-workers --workers 2
  run ray-2-nodes --engine ray --address 127.0.0.1:6380
done
diff -r "$OUT/local-2-workers/$CAT" "$OUT/ray-2-nodes/$CAT" >/dev/null && echo "same bytes: yes" || echo "same bytes: NO"
