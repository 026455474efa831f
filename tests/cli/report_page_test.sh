#!/bin/sh
# The report page as a person sees it: two short campaigns add their records to a history
# folder, then a night of fuzzing (FUZZ_NIGHT, nightly.sh's report as the test writes it, with
# `crosscheck fuzz-history`); `crosscheck report` writes the page, and headless Chromium renders it. Fails on any
# console message, on an image the page could not load or a script error (the page's own check,
# read from the rendered DOM), or on a section missing; leaves the screenshot in WORK.
# Usage: report_page_test.sh CROSSCHECK CORPORA WORK FUZZ_NIGHT
set -u
tool=$1 corpora=$2 work=$3 night=$4
fail() { echo "report page: $*" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work" || fail "cannot make $work"
for seed in 1 2; do
  "$tool" campaign --query sphere_sphere_distance --query obb_obb --query tri_obb_distance --seconds 3 --seed "$seed" \
    --workers 2 --history "$work/history" --corpora "$corpora" --out "$work/new" --max-new 4 > "$work/campaign-$seed.log" 2>&1
  status=$?
  [ "$status" -le 1 ] || fail "campaign --seed $seed exited $status (see $work/campaign-$seed.log)"
done
[ "$(ls "$work/history" | wc -l)" -eq 2 ] || fail "two campaigns left $(ls "$work/history" | wc -l) records"
for record in "$work"/history/*.json; do
  /usr/bin/python3 -c 'import json, sys
r = json.load(open(sys.argv[1]))
assert r["format"] == "crosscheck history" and r["run"] == "campaign", "not a campaign record"
assert r["seconds"] >= r["seconds_of_cases"] > 0, "the whole run shorter than its cases"
assert all("group" in f and "parties" in f for f in r["findings"]), "a finding without its group"
assert all("disagreement" in f for f in r["findings"] if f["class"] not in ("boundary", "undecided", "out_of_contract")), "a finding without its disagreement"' "$record" ||
    fail "$record: not the record a campaign writes"
done
# The night after the campaigns, with one finding of a group no campaign had, on a stored case.
sed -e "s/2026-12-01T02:00:00Z/$(date -u -d '+2 min' +%Y-%m-%dT%H:%M:%SZ)/" \
    -e "s|@CASE@|$corpora/obb_obb/3ac9cee532e5b825.json|" "$night" > "$work/night.json" || fail "cannot write $work/night.json"
"$tool" fuzz-history "$work/night.json" --history "$work/history" > "$work/fuzz-history.log" 2>&1 ||
  fail "fuzz-history failed: $(cat "$work/fuzz-history.log")"
/usr/bin/python3 -c 'import json, sys
r = json.load(open(sys.argv[1]))
assert r["format"] == "crosscheck history" and r["run"] == "fuzz" and r["versions"]["FCL"], "not a fuzz record"
assert r["targets"]["obb_obb"]["coverage_after"] == 1733 and r["queries"]["obb_obb"]["oracle_defect"] == 1, "figures lost"
assert r["findings"][0]["disagreement"] == "obb_obb.false_hit", "the finding lost its group"' \
  "$(sed -n 's/^history: //p' "$work/fuzz-history.log")" || fail "the fuzz record is not the night's"
"$tool" report "$work/history" --out "$work/page" > "$work/report.log" 2>&1 || fail "report failed: $(cat "$work/report.log")"
page="$work/page/index.html"
[ -s "$page" ] || fail "no $page"
browser() {
  chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --enable-logging=stderr --v=0 \
    --virtual-time-budget=5000 --window-size=1400,3000 "$@" "file://$page"
}
browser --screenshot="$work/screenshot.png" > /dev/null 2> "$work/chromium-screenshot.log" || fail "chromium failed to render"
browser --dump-dom > "$work/dom.html" 2> "$work/chromium-dom.log" || fail "chromium failed to load the page"
if grep -h ':CONSOLE' "$work/chromium-screenshot.log" "$work/chromium-dom.log"; then fail "console messages above"; fi
grep -q 'data-self-check="ok"' "$work/dom.html" ||
  fail "the page's own check: $(grep -o 'data-self-check="[^"]*"' "$work/dom.html" || echo 'it never ran')"
for section in header grid trends new ledger findings fuzzing; do
  grep -q "id=\"$section\"" "$work/dom.html" || fail "no section \"$section\""
done
[ "$(grep -c '<img ' "$work/dom.html")" -ge 4 ] || fail "fewer than four plots (the fuzz plot among them)"
grep -q 'disagreement <code>obb_obb.false_hit</code>' "$work/dom.html" || fail "no card for the night's new group"
[ -s "$work/screenshot.png" ] || fail "no screenshot"
echo "report page: $(wc -c < "$page") bytes, screenshot $work/screenshot.png"
