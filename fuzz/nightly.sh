#!/usr/bin/env bash
# The nightly fuzzing job. Every fuzz target runs for its share of a time budget under libFuzzer
# with -jobs/-workers; the new corpus is merged into the stored seeds (corpora/<query>/seed, by
# -merge=1); each new finding becomes a minimised case file in corpora/new/<query>/ (through
# `crosscheck fuzz-case` and `crosscheck shrink`); and a report is written in Markdown and JSON:
# per target the executions per second, the coverage (features) before and after, and the
# findings by class; with --history, the night is added to a history folder as a record of its
# own (`crosscheck fuzz-history`), which `crosscheck report` draws beside the campaigns. Ctrl-C
# stops the fuzzers and still merges, converts and reports what was found.
#
#   fuzz/nightly.sh [--minutes 10] [--jobs 2] [--report build/fuzz-report] [--targets "KIND ..."]
#                   [--max-shrink 5] [--subject PATH.so] [--history DIR]
#
# --subject fuzzes a shared library (include/crosscheck/subject.h) instead of crosscheck's own:
# the targets load it (CROSSCHECK_SUBJECT), and only the kinds it answers are run.
#
# Every finding is classified; the first of each kind of finding (same class, parties, features
# and margin decade), up to --max-shrink per target, is minimised into corpora/new/.
set -u

root=$(cd "$(dirname "$0")/.." && pwd)
minutes=10
jobs=2
report="$root/build/fuzz-report"
targets=""  # default: every query kind (the fuzz build lists them in fuzz/targets.txt)
max_shrink=5
subject=""
history=""
while [ $# -gt 0 ]; do
  case "$1" in
    --minutes) minutes=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --report) report=$2; shift 2 ;;
    --targets) targets=$2; shift 2 ;;
    --max-shrink) max_shrink=$2; shift 2 ;;
    --subject) subject=$(realpath "$2") || exit 2; shift 2 ;;
    --history) history=$(realpath -m "$2") || exit 2; shift 2 ;;
    *) echo "usage: $0 [--minutes M] [--jobs J] [--report DIR] [--targets \"Q ...\"] [--max-shrink N] [--subject PATH.so] [--history DIR]" >&2; exit 2 ;;
  esac
done

cd "$root" || exit 2
./.ci/deps || exit 2
cmake --preset fuzz > /dev/null || exit 2
[ -n "$targets" ] || targets=$(cat "$root/build/fuzz/fuzz/targets.txt") || exit 2
subject_flags=()
if [ -n "$subject" ]; then
  # The kinds the subject answers: those whose crosscheck_<kind> it exports.
  answered=""
  for t in $targets; do
    nm -D --defined-only "$subject" 2>/dev/null | grep -q " crosscheck_$t\$" && answered="$answered $t"
  done
  [ -n "$answered" ] || { echo "nightly: --subject $subject answers none of: $targets" >&2; exit 2; }
  targets=$answered
  subject_flags=(--subject "$subject")
fi
cmake --build --preset fuzz --target $(printf 'fuzz_%s ' $targets) || exit 2
cmake --preset release > /dev/null && cmake --build --preset release --target crosscheck || exit 2
crosscheck="$root/build/release/crosscheck"
bin="$root/build/fuzz/fuzz"

stopped=0
trap 'stopped=1' INT TERM
# An abandoned libccd call (one that would never return) leaks FCL's GJK objects by design.
export LSAN_OPTIONS="suppressions=$root/tests/lsan.supp:print_suppressions=0"

rm -rf "$report"
mkdir -p "$report"
count=$(echo $targets | wc -w)
budget=$(( minutes * 60 / count ))
[ "$budget" -ge 1 ] || budget=1
started=$(date -u +%Y-%m-%dT%H:%M:%SZ)
night_begin=$(date +%s)
# A JSON string of text (paths and finding keys hold no control characters).
json_string() { local s=${1//\\/\\\\}; s=${s//\"/\\\"}; printf '"%s"' "$s"; }
json_findings=""

# The features and coverage libFuzzer reports after loading a corpus: "INITED cov: C ft: F".
coverage() { "$bin/fuzz_$1" -runs=0 "$2" 2>&1 | sed -n 's/.*INITED cov: \([0-9]*\) ft: \([0-9]*\).*/\1 \2/p' | tail -n 1; }

json_targets=""
markdown=""
for t in $targets; do
  seeds="$root/corpora/$t/seed"
  work="$report/work/$t"; logs="$report/logs/$t"; artifacts="$report/artifacts/$t"
  mkdir -p "$work" "$logs" "$artifacts" "$seeds"
  read -r cov_before ft_before <<< "$(coverage "$t" "$seeds")"
  seconds=0
  ran=false
  if [ "$stopped" = 0 ]; then
    ran=true
    echo "fuzzing $t for ${budget}s with $jobs jobs"
    begin=$(date +%s)
    ( cd "$logs" && CROSSCHECK_SUBJECT="$subject" CROSSCHECK_FUZZ_FINDINGS="$report/findings" "$bin/fuzz_$t" -max_total_time="$budget" \
        -jobs="$jobs" -workers="$jobs" -dict="$bin/$t.dict" -artifact_prefix="$artifacts/" \
        -print_final_stats=1 -timeout=10 "$work" "$seeds" > /dev/null 2>&1 )
    seconds=$(( $(date +%s) - begin ))
  fi
  # A target that stopped long before its budget (without Ctrl-C) did not fuzz: say so.
  status=ok
  if [ "$ran" = true ] && [ "$stopped" = 0 ] && [ "$seconds" -lt $(( budget / 2 )) ]; then status=stopped-early; fi
  # Executions per second: summed over the jobs' final statistics.
  execs=$(cat "$logs"/fuzz-*.log 2>/dev/null | sed -n 's/^stat::average_exec_per_sec: *\([0-9]*\)/\1/p' |
          awk '{s += $1} END {print s + 0}')
  # The new corpus into the stored seeds: only inputs that add coverage are kept.
  "$bin/fuzz_$t" -merge=1 "$seeds" "$work" > "$logs/merge.log" 2>&1
  read -r cov_after ft_after <<< "$(coverage "$t" "$seeds")"
  # Findings: crashes and timeouts libFuzzer kept, and the inputs the target recorded.
  declare -A by_class=([impl_bug]=0 [oracle_defect]=0 [oracle_crash]=0 [undecided]=0 [other]=0)
  declare -A seen=()
  shrunk=0
  for f in "$artifacts"/* "$report/findings/$t"/*; do
    [ -f "$f" ] || continue
    # "<input> <class> <case file> <group of its disagreement> <kind of finding...>"
    line=$("$crosscheck" fuzz-case "$t" "$f" --out "$report/cases" "${subject_flags[@]}")
    class=$(echo "$line" | awk '{print $2}')
    case_file=$(echo "$line" | awk '{print $3}')
    group=$(echo "$line" | awk '{print $4}')
    key=$(echo "$line" | cut -d' ' -f5-)
    [ -n "$json_findings" ] && json_findings+=","
    json_findings+=$(printf '\n    {"query": %s, "class": %s, "disagreement": %s, "group": %s, "case_file": %s}' \
      "$(json_string "$t")" "$(json_string "$class")" "$(json_string "$group")" "$(json_string "$key")" "$(json_string "$case_file")")
    if [ -n "${by_class[$class]+x}" ]; then by_class[$class]=$(( by_class[$class] + 1 )); else by_class[other]=$(( by_class[other] + 1 )); fi
    if [ -f "$case_file" ] && [ -z "${seen[$key]+x}" ] && [ "$shrunk" -lt "$max_shrink" ]; then
      seen[$key]=1
      shrunk=$(( shrunk + 1 ))
      written=$("$crosscheck" shrink "$case_file" -o "$root/corpora/new/$t/" "${subject_flags[@]}" | sed -n 's/^  written to //p')
      # Already stored elsewhere under corpora/ (a known case): not a new one.
      if [ -n "$written" ] && find "$root/corpora" -path "$root/corpora/new" -prune -o -name "$(basename "$written")" -print | grep -q .; then
        rm -f "$written"
      fi
    fi
  done
  unset seen
  echo "$t ($status): ${execs} exec/s, features ${ft_before:-0} -> ${ft_after:-0}, impl_bug ${by_class[impl_bug]}, oracle_defect ${by_class[oracle_defect]}, oracle_crash ${by_class[oracle_crash]}"
  markdown+="| $t | $status | $seconds | $execs | ${ft_before:-0} | ${ft_after:-0} | ${cov_before:-0} | ${cov_after:-0} | ${by_class[impl_bug]} | ${by_class[oracle_defect]} | ${by_class[oracle_crash]} | ${by_class[undecided]} |"$'\n'
  [ -n "$json_targets" ] && json_targets+=","
  json_targets+=$(printf '\n    "%s": {"status": "%s", "seconds": %s, "execs_per_second": %s, "features_before": %s, "features_after": %s, "coverage_before": %s, "coverage_after": %s, "findings": {"impl_bug": %s, "oracle_defect": %s, "oracle_crash": %s, "undecided": %s, "other": %s}}' \
    "$t" "$status" "$seconds" "$execs" "${ft_before:-0}" "${ft_after:-0}" "${cov_before:-0}" "${cov_after:-0}" \
    "${by_class[impl_bug]}" "${by_class[oracle_defect]}" "${by_class[oracle_crash]}" "${by_class[undecided]}" "${by_class[other]}")
  unset by_class
done

interrupted=$([ "$stopped" = 1 ] && echo true || echo false)
{
  echo "# Nightly fuzzing report"
  echo
  echo "Started $started; $minutes minutes over $count targets, $jobs jobs each; interrupted: $interrupted."
  echo "Features and coverage are libFuzzer's, over the stored seeds before and after merging the new corpus."
  echo "Findings are minimised into corpora/new/<query>/ for triage."
  echo
  echo "| target | status | seconds | exec/s | features before | features after | coverage before | coverage after | impl_bug | oracle_defect | oracle_crash | undecided |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
  printf '%s' "$markdown"
} > "$report/report.md"
printf '{\n  "started": "%s", "seconds": %s, "minutes": %s, "jobs": %s, "interrupted": %s, "subject": %s,\n  "targets": {%s\n  },\n  "findings": [%s\n  ]\n}\n' \
  "$started" "$(( $(date +%s) - night_begin ))" "$minutes" "$jobs" "$interrupted" "$(json_string "$subject")" \
  "$json_targets" "$json_findings" > "$report/report.json"
echo "report: $report/report.md and $report/report.json"
# The night in the history folder; a record that could not be added fails the run (exit 3).
if [ -n "$history" ] && ! "$crosscheck" fuzz-history "$report/report.json" --history "$history"; then exit 3; fi
impl_bugs=$(grep -o '"impl_bug": [0-9]*' "$report/report.json" | awk '{s += $2} END {print s + 0}')
[ "$impl_bugs" -eq 0 ]
