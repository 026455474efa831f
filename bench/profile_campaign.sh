#!/bin/bash
# Where a campaign's time goes, per query kind: perf record of a one-worker campaign on each kind,
# every sample's self time summed by the part of a case it falls in, printed as a Markdown table
# with the kind's cases per second (slowed by perf, about 10%: compare kinds, not runs).
#
#   bench/profile_campaign.sh [--seconds S] [KIND ...]    (default: every kind, 6 s each)
#
# Parts, by the shared object a sample falls in and, within crosscheck, its function's namespace:
#   library      crosscheck's own code outside the parts below (src/collide)
#   exact        cc::exact (oracle/exact), outside GMP
#   GMP          libgmp: the exact reference's rationals
#   malloc       the C library's malloc, free and realloc (most are GMP's temporaries, some the
#                harness's; perf without call graphs cannot tell)
#   FCL, Bullet, ODE, Chipmunk   the peers' libraries and their adapters in oracle/
#   harness      cc::harness and cc::tool (generation, judging, case files), JSON, CLI
#   kernel       system calls, page faults, the worker's pipe
#   other        the rest of libc, libstdc++, libm, the loader
# Builds build/release's crosscheck if missing (the release preset). Needs perf (Debian's
# linux-perf) and kernel.perf_event_paranoid <= 2.
set -euo pipefail

usage="usage: bench/profile_campaign.sh [--seconds S] [KIND ...]"
root=$(cd "$(dirname "$0")/.." && pwd)
tool="$root/build/release/crosscheck"
seconds=6
kinds=()
while [ $# -gt 0 ]; do
  case "$1" in
    -h|--help) echo "$usage"; exit 0 ;;
    --seconds)
      [ $# -ge 2 ] && [[ "$2" =~ ^[0-9]+$ ]] && [ "$2" -ge 1 ] && [ "$2" -le 3600 ] ||
        { echo "profile_campaign.sh: --seconds must be a whole number of seconds in [1, 3600]" >&2; exit 2; }
      seconds=$2; shift 2 ;;
    -*) echo "profile_campaign.sh: unknown flag $1" >&2; echo "$usage" >&2; exit 2 ;;
    *) kinds+=("$1"); shift ;;
  esac
done
command -v perf >/dev/null || { echo "profile_campaign.sh: perf is missing (Debian's linux-perf)" >&2; exit 2; }
[ -x "$tool" ] || (cd "$root" && cmake --preset release >/dev/null && cmake --build --preset release --target crosscheck >/dev/null)

# The kinds the tool knows, from its help; each asked for must be one of them.
known=$("$tool" campaign --help | sed -n 's/^Query kinds: //p' | tr -d ' ' | tr ',' '\n')
[ ${#kinds[@]} -gt 0 ] || mapfile -t kinds <<<"$known"
for k in "${kinds[@]}"; do
  grep -qx -- "$k" <<<"$known" || { echo "profile_campaign.sh: $k is not a query kind (crosscheck campaign --help lists them)" >&2; exit 2; }
done

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cd "$root"
for k in "${kinds[@]}"; do
  perf record -q -o "$scratch/$k.data" -F 999 -- "$tool" campaign --query "$k" --seconds "$seconds" --workers 1 \
    --json "$scratch/$k.json" --out "$scratch/new" --max-new 0 --max-print 0 >/dev/null 2>&1 || true
  [ -f "$scratch/$k.json" ] ||
    { echo "profile_campaign.sh: the $k campaign under perf wrote no summary (is perf allowed? kernel.perf_event_paranoid <= 2)" >&2; exit 1; }
  perf report -i "$scratch/$k.data" --no-children --sort dso,sym --stdio 2>/dev/null | grep '%' >"$scratch/$k.txt" || true
done

python3 - "$scratch" "${kinds[@]}" <<'EOF'
import json, re, sys
scratch, kinds = sys.argv[1], sys.argv[2:]
parts = ['library', 'exact', 'GMP', 'malloc', 'FCL', 'Bullet', 'ODE', 'Chipmunk', 'harness', 'kernel', 'other']
peers = [('FCL', r'libfcl|libccd', r'fcl_oracle|fcl::'), ('Bullet', r'Bullet|LinearMath', r'bullet_oracle|\bbt[A-Z]'),
         ('ODE', r'libode', r'ode_oracle|\bd[A-Z][a-z]+'), ('Chipmunk', r'chipmunk', r'chipmunk_oracle|\bcp[A-Z]')]

def part(dso, symbol):
    if 'libgmp' in dso: return 'GMP'
    if 'kernel' in dso: return 'kernel'
    if dso.startswith('libc.so') and re.search(r'malloc|free|realloc|calloc|_int_|tcache', symbol): return 'malloc'
    for name, library, adapter in peers:
        if re.search(library, dso) or ('crosscheck' in dso and re.search(adapter, symbol)): return name
    if 'crosscheck' in dso:
        if 'cc::exact' in symbol: return 'exact'
        if re.search(r'cc::harness|cc::tool|nlohmann|CLI::', symbol): return 'harness'
        return 'library'
    return 'other'

print('| kind | cases/s | ' + ' | '.join(parts) + ' |')
print('|---|---|' + '---|' * len(parts))
for kind in kinds:
    share = dict.fromkeys(parts, 0.0)
    for line in open(f'{scratch}/{kind}.txt'):
        m = re.match(r'\s*([\d.]+)%\s+(\S+)\s+\[[.k]\]\s+(.*)', line)
        if m: share[part(m.group(2), m.group(3))] += float(m.group(1))
    rate = json.load(open(f'{scratch}/{kind}.json'))['queries'][kind]['cases_per_second']
    print(f'| {kind} | {rate:.0f} | ' + ' | '.join(f'{share[p]:.0f}%' for p in parts) + ' |')
EOF
