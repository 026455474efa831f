#!/bin/sh
# Runs every benchmark and prints the table of ratios (FCL time / library time, medians of
# repeated runs); writes the JSON to build/bench/bench.json (or $1) and, for a full run (no extra
# flags), the page docs/performance.md: the table under a header with the date, the commit, the
# processor and the command, replacing the page of the last full run. What each row measures is
# in docs/benchmarks.md.
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
command_line="bench/run.sh${*:+ $*}"
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
"$build/bench/crosscheck_bench" --campaign-json "$scratch/campaign.json" --json "$out" "$@" >"$scratch/table.md"
cat "$scratch/table.md"
echo "bench: JSON written to $out" >&2

if [ $# -gt 0 ]; then
  echo "bench: extra flags given ($*): docs/performance.md is left as it was (it holds full runs only)" >&2
  exit 0
fi
commit=$(git -C "$root" rev-parse --short=12 HEAD 2>/dev/null || echo unknown)
[ "$commit" = unknown ] || git -C "$root" diff --quiet HEAD -- 2>/dev/null || commit="$commit-dirty"
processor=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo 2>/dev/null | head -n 1)
{
  echo "# Performance against FCL"
  echo
  echo "Written by \`bench/run.sh\`, which replaces it at each full run; how to read it and what each row"
  echo "measures: [benchmarks.md](benchmarks.md)."
  echo
  echo "- date: $(date -u '+%Y-%m-%d %H:%M') UTC"
  echo "- commit: $commit"
  echo "- processor: ${processor:-unknown}, $(nproc) cores"
  echo "- command: \`$command_line\`"
  echo
  cat "$scratch/table.md"
} >"$scratch/performance.md"
mv "$scratch/performance.md" "$root/docs/performance.md"
echo "bench: docs/performance.md written" >&2
