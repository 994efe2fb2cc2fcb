#!/usr/bin/env bash
# The figures of docs/performance.md, "Sweeps on Spark": the same bumper sweep on the sweep's own
# engine, on Spark's local[2] and on a two-worker cluster of this machine (rp1 cluster), with N and
# 2N runs, short (60 simulated seconds) and long (ten simulated minutes). From two sizes: the cost of one more run
# ((T(2N) - T(N)) / N) and the start-up (T(N) - N x that). Needs `gradle installDist` first.
#   rp1-spark/src/bench/sweeps.sh [N_SHORT] [N_LONG]
set -euo pipefail
repo=$(cd "$(dirname "$0")/../../.." && pwd)
rp1="$repo/build/install/rp1/bin/rp1"
short=${1:-64}
long=${2:-8}
work=$(mktemp -d)
trap 'kill $cluster 2>/dev/null || true; wait 2>/dev/null; rm -rf "$work"' EXIT
cd "$work"
sed 's/^maxSimulationTime=.*/maxSimulationTime=60/' "$repo/Properties/bumper.ini" > short.ini
sed 's/^maxSimulationTime=.*/maxSimulationTime=600/' "$repo/Properties/bumper.ini" > long.ini

"$rp1" cluster --workers 2 --dir "$work/cluster" > cluster.out 2>&1 &
cluster=$!
while ! grep -q 'spark://' cluster.out; do sleep 0.5; kill -0 $cluster; done
master=$(grep -o 'spark://[0-9.:]*' cluster.out | head -1)

seconds() {  # the wall seconds of one sweep
    local start end
    start=$(date +%s.%N)
    "$rp1" sweep "$@" > /dev/null 2>&1
    end=$(date +%s.%N)
    echo "$end - $start" | bc -l
}

figure() {  # ini n label args...
    local ini=$1 n=$2 label=$3
    shift 3
    local one two
    one=$(seconds -p "$ini" --seeds 1-"$n" --out "o1" "$@")
    two=$(seconds -p "$ini" --seeds 1-$((2 * n)) --out "o2" "$@")
    local per=$(echo "($two - $one) / $n" | bc -l)
    printf '%-6s %-22s %3d runs %7.2f s, %3d runs %7.2f s: %6.3f s per run, %6.1f runs/s, start-up %5.1f s\n' \
        "$ini" "$label" "$n" "$one" $((2 * n)) "$two" "$per" "$(echo "1 / $per" | bc -l)" \
        "$(echo "$one - $n * $per" | bc -l)"
    rm -rf o1 o2
}

for ini in short.ini long.ini; do
    n=$short
    [ "$ini" = long.ini ] && n=$long
    figure "$ini" "$n" "own engine, --jobs 2" --jobs 2
    figure "$ini" "$n" "local[2]" --master 'local[2]'
    figure "$ini" "$n" "cluster, 2 workers" --master "$master"
done
