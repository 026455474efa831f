#!/bin/sh
# Runs every benchmark of issue 7 and prints the table of ratios (FCL time / library time,
# medians of repeated runs); writes the JSON to build/bench/bench.json (or $1).
#
#   bench/run.sh [OUT.json] [extra crosscheck_bench flags...]
#
# Steps: configure and build build/bench (Release, g++, one job: the machine is shared),
# a 39-second harness campaign over every query kind (`crosscheck campaign --json`, exact
# reference included, nothing written to corpora/; FCL's assertion messages from crashing
# workers go to its log), then crosscheck_bench, which adds the campaign's cases/s to its table.
# About six minutes in all on two cores, most of it the library's builds of the 100k mesh.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build/bench"
out="${1:-$build/bench.json}"
[ $# -gt 0 ] && shift

if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=g++ >/dev/null
fi
cmake --build "$build" -j1 --target crosscheck crosscheck_bench >/dev/null

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
echo "bench: harness campaign, every query kind, 39 s" >&2
(cd "$root" && "$build/crosscheck" campaign --seconds 39 --seed 1 --json "$scratch/campaign.json" \
  --out "$scratch/new" --max-new 0 --max-print 0 >"$scratch/campaign.txt" 2>&1) || true
[ -f "$scratch/campaign.json" ] || { echo "bench: the campaign wrote no JSON; see its output:" >&2; cat "$scratch/campaign.txt" >&2; exit 1; }

cd "$root"
"$build/bench/crosscheck_bench" --campaign-json "$scratch/campaign.json" --json "$out" "$@"
echo "bench: JSON written to $out" >&2
