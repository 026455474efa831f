#!/bin/sh
# Where one benchmark spends its time: perf record of crosscheck_bench on the benchmarks a
# filter selects, then the source lines taking at least 1.5% of the samples (inlined code is
# attributed to its own lines).
#
#   bench/profile.sh FILTER [SECONDS]      e.g. bench/profile.sh 'obb_obb/mixed/lib$' 3
#
# Builds build/profile (Release flags plus -g, one job). Needs perf (Debian's linux-perf) and
# kernel.perf_event_paranoid <= 2.
set -eu
[ $# -ge 1 ] || { echo "usage: bench/profile.sh FILTER [SECONDS]" >&2; exit 2; }
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build/profile"
filter=$1
seconds=${2:-3}
if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS=-g -DCMAKE_CXX_COMPILER=g++ >/dev/null
fi
cmake --build "$build" -j1 --target crosscheck_bench >/dev/null
data=$(mktemp)
trap 'rm -f "$data"' EXIT
cd "$root"
perf record -q -o "$data" -F 2000 -- "$build/bench/crosscheck_bench" --benchmark_filter="$filter" \
  --benchmark_repetitions=1 --benchmark_min_time="$seconds" >/dev/null 2>&1
perf report -i "$data" --no-children --sort srcline --percent-limit 1.5 --stdio 2>/dev/null |
  grep -v '^#' | grep -v '^$' | sed 's/^ *//' | cut -c1-150
