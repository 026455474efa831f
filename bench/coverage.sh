#!/bin/bash
# Line and branch coverage per folder (gcovr), from the tests of one ctest label: by default the
# property tests alone, to see what the generators and properties reach without the unit tests.
#
#   bench/coverage.sh [--label LABEL] [--tests REGEX] [--out FILE]
#
#   --label LABEL   the ctest label whose tests run (default property; `all` runs every test);
#                   only the executables of that label (and what their tests run) are built
#   --tests REGEX   of those, only the tests whose names match REGEX (ctest -R)
#   --out FILE      the page written (default docs/coverage.md; `-` prints it only)
#
# Steps: installs gcovr with apt-get if it is missing (as root or through sudo, as .ci/deps does);
# configures and builds the `coverage` preset (build/coverage: g++ -Og --coverage) under nice,
# two jobs; deletes every .gcda (zeroes the counters); runs `ctest --preset coverage -L LABEL`;
# runs gcovr over the repository's own sources (src/, oracle/; not build/, tests/ or system
# headers; throw branches and unreachable branches left out); prints per folder lines and
# branches covered, then the branches each generator reaches (src/harness/generation/ per file,
# and in src/harness/kinds/ each function that draws from a ValueSource or is named generate*),
# and writes them to the page with the date, commit, processor and command.
# -Og, not -O0: a build without optimisation has the library's scalar kernels only (the vector
# kernels need inlining, see src/collide/simd.cpp), which would leave the vector kernels
# uncovered.
# Code that runs in a forked child which ends with _Exit (src/harness/processes/child.cpp) writes
# no counters: it shows as not covered.
set -euo pipefail

usage="usage: bench/coverage.sh [--label LABEL] [--tests REGEX] [--out FILE]"
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build/coverage"
command_line="bench/coverage.sh${*:+ $*}"

label=property
tests=""
out="$root/docs/coverage.md"
while [ $# -gt 0 ]; do
  case "$1" in
    -h|--help) echo "$usage"; exit 0 ;;
    --label|--tests|--out)
      [ $# -ge 2 ] || { echo "coverage.sh: $1 needs a value" >&2; echo "$usage" >&2; exit 2; }
      case "$1" in
        --label)
          [[ "$2" =~ ^[A-Za-z0-9_.-]+$ ]] || { echo "coverage.sh: --label must be a label name (letters, digits, _ . -), not '$2'" >&2; exit 2; }
          label=$2 ;;
        --tests)
          [ -n "$2" ] || { echo "coverage.sh: --tests needs a non-empty REGEX" >&2; exit 2; }
          tests=$2 ;;
        --out)
          [ -n "$2" ] || { echo "coverage.sh: --out needs a file (or -)" >&2; exit 2; }
          if [ "$2" = - ]; then out=-; else
            case "$2" in /*) out=$2 ;; *) out="$PWD/$2" ;; esac
            [ -d "$(dirname "$out")" ] || { echo "coverage.sh: --out: no folder $(dirname "$out")" >&2; exit 2; }
            [ ! -d "$out" ] || { echo "coverage.sh: --out: $out is a folder" >&2; exit 2; }
          fi ;;
      esac
      shift 2 ;;
    *) echo "coverage.sh: unknown flag $1" >&2; echo "$usage" >&2; exit 2 ;;
  esac
done

# gcovr, installed as .ci/deps installs what is missing.
if ! command -v gcovr >/dev/null 2>&1; then
  echo "coverage.sh: installing gcovr" >&2
  if [ "$(id -u)" -eq 0 ]; then
    as_root=""
  elif command -v sudo >/dev/null 2>&1; then
    as_root="sudo"
  else
    echo "coverage.sh: gcovr is missing; run this script as root, install sudo, or apt-get install gcovr" >&2
    exit 1
  fi
  $as_root env DEBIAN_FRONTEND=noninteractive apt-get update -qq
  $as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends gcovr >/dev/null
fi

cd "$root"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

echo "coverage.sh: configuring the coverage preset" >&2
nice -n 19 cmake --preset coverage >"$scratch/configure.log" 2>&1 ||
  { cat "$scratch/configure.log" >&2; exit 1; }

# The targets the label's tests need. A GoogleTest executable's tests exist only once it is built
# (gtest_discover_tests), so its label is read from the discovery step in build.ninja; a plain
# add_test test names its programs by path, built by the targets that make them.
if [ "$label" = all ]; then
  targets=(all)
  label_args=()
else
  label_args=(-L "^${label}\$")
  mapfile -t targets < <(python3 - "$build" "$label" <<'EOF'
import json, re, subprocess, sys
build, label = sys.argv[1], sys.argv[2]
found = []
ninja = open(f"{build}/build.ninja", encoding="utf-8", errors="replace").read()
for m in re.finditer(r'-D TEST_TARGET=(\S+) .*?"TEST_PROPERTIES=([^"]*)"', ninja):
    items = m.group(2).split(";")
    labels, i = [], 0
    while i < len(items):
        if items[i] == "LABELS":
            i += 1
            while i < len(items) and not re.fullmatch(r"[A-Z_]+", items[i]):
                labels.append(items[i]); i += 1
        else:
            i += 1
    if label in labels and m.group(1) not in found:
        found.append(m.group(1))
shown = subprocess.run(["ctest", "--test-dir", build, "-N", "-L", f"^{label}$", "--show-only=json-v1"],
                       capture_output=True, text=True, check=True).stdout
# A test's command (absent from ctest's JSON while its program is not built), from its add_test.
commands = {}
for testfile in subprocess.run(["find", build, "-name", "CTestTestfile.cmake"], capture_output=True,
                               text=True, check=True).stdout.split():
    for line in open(testfile, encoding="utf-8", errors="replace"):
        m = re.match(r"add_test\(\[=\[(.*?)\]=\] (.*)\)$", line.strip())
        if m:
            commands[m.group(1)] = m.group(2)
for test in json.loads(shown).get("tests", []):
    for word in [" ".join(test.get("command", [])), commands.get(test["name"], "")]:
        for path in re.findall(re.escape(build) + r"/[^ ;\"']+", word):
            rel = path[len(build) + 1:]
            if rel in found or rel.rsplit("/", 1)[-1] in found:  # a test executable named above
                continue
            if subprocess.run(["ninja", "-C", build, "-t", "query", rel], capture_output=True).returncode == 0:
                found.append(rel)
for t in found:
    print(t)
EOF
  )
  if [ ${#targets[@]} -eq 0 ]; then
    echo "coverage.sh: --label $label: no test has that label" >&2
    exit 2
  fi
fi

echo "coverage.sh: building ${targets[*]} (nice, 2 jobs)" >&2
build_start=$(date +%s)
nice -n 19 cmake --build --preset coverage -j2 --target "${targets[@]}" >"$scratch/build.log" 2>&1 ||
  { tail -50 "$scratch/build.log" >&2; exit 1; }
build_seconds=$(( $(date +%s) - build_start ))

ctest_args=(--preset coverage "${label_args[@]}")
[ -n "$tests" ] && ctest_args+=(-R "$tests")
count=$(ctest "${ctest_args[@]}" -N 2>/dev/null | sed -n 's/^Total Tests: *//p')
if [ -z "$count" ] || [ "$count" -eq 0 ]; then
  if [ -n "$tests" ]; then echo "coverage.sh: --tests $tests selects no test of label $label" >&2
  else echo "coverage.sh: --label $label selects no test" >&2; fi
  exit 2
fi
if ctest "${ctest_args[@]}" -N | grep -q '_NOT_BUILT$'; then
  echo "coverage.sh: some tests of label $label were not built:" >&2
  ctest "${ctest_args[@]}" -N | grep '_NOT_BUILT$' >&2
  exit 1
fi

find "$build" -name '*.gcda' -delete
echo "coverage.sh: running $count tests: ctest ${ctest_args[*]}" >&2
test_start=$(date +%s)
test_status=0
nice -n 19 ctest "${ctest_args[@]}" >"$scratch/ctest.log" 2>&1 || test_status=$?
test_seconds=$(( $(date +%s) - test_start ))
tail -3 "$scratch/ctest.log" >&2
failed=$(sed -n '/tests failed out of/,$p' "$scratch/ctest.log" | grep -E '^\s+[0-9]+ - ' || true)

echo "coverage.sh: gcovr" >&2
root_re=$(printf '%s' "$root" | sed 's/[][\.*^$+?(){}|]/\\&/g')
nice -n 19 gcovr --root "$root" --object-directory "$build" \
  --filter "$root_re/src/" --filter "$root_re/oracle/" \
  --exclude "$root_re/build/" --exclude "$root_re/tests/" \
  --exclude-throw-branches --exclude-unreachable-branches -j 2 \
  --json "$scratch/coverage.json" --json-summary "$scratch/summary.json" \
  "$build" >"$scratch/gcovr.log" 2>&1 || { cat "$scratch/gcovr.log" >&2; exit 1; }

export CC_ROOT="$root" CC_COMMAND="$command_line" CC_BUILD_SECONDS="$build_seconds" \
  CC_TEST_SECONDS="$test_seconds" CC_TEST_COUNT="$count" CC_FAILED="$failed" CC_LABEL="$label" \
  CC_TESTS="$tests" CC_GCOVR="$(gcovr --version | head -1)" CC_GCC="$(g++ --version | head -1)"
python3 - "$scratch/summary.json" "$scratch/coverage.json" "$scratch/page.md" <<'EOF'
import datetime, json, os, re, subprocess, sys
summary = json.load(open(sys.argv[1]))
detail = json.load(open(sys.argv[2]))
root = os.environ["CC_ROOT"]

def rel(name):
    return os.path.relpath(name, root) if os.path.isabs(name) else name

files = {rel(f["filename"]): f for f in summary["files"]}

def cell(covered, total):
    return f"{covered}/{total} ({100.0 * covered / total:.1f}%)" if total else "-"

def folder_row(folder):
    chosen = [f for n, f in files.items() if n.startswith(folder + "/")]
    lc = sum(f["line_covered"] for f in chosen); lt = sum(f["line_total"] for f in chosen)
    bc = sum(f["branch_covered"] for f in chosen); bt = sum(f["branch_total"] for f in chosen)
    return len(chosen), lc, lt, bc, bt

def subfolders(folder):
    names = set()
    for n in files:
        if n.startswith(folder + "/"):
            rest = n[len(folder) + 1:]
            if "/" in rest:
                names.add(folder + "/" + rest.split("/")[0])
    return sorted(names)

folders = []
for top in ["src/collide", "src/harness", "src/tool", "oracle"]:
    folders.append(top)
    folders += ["  " + s for s in subfolders(top)]

folder_lines = ["| folder | files | lines | branches |", "|---|---:|---:|---:|"]
for f in folders:
    name = f.strip()
    n, lc, lt, bc, bt = folder_row(name)
    shown = ("&nbsp;&nbsp;" if f.startswith("  ") else "") + f"`{name}/`"
    folder_lines.append(f"| {shown} | {n} | {cell(lc, lt)} | {cell(bc, bt)} |")
n, lc, lt, bc, bt = (sum(x) for x in zip(*(folder_row(t) for t in ["src", "oracle"])))
folder_lines.append(f"| **all of src/ and oracle/** | {n} | {cell(lc, lt)} | {cell(bc, bt)} |")

# Generators: every file of src/harness/generation/ whole; in src/harness/kinds/, the functions
# that draw from a ValueSource or are named generate* (with their lambdas), by line range: from a
# function's first line to the next function that is not nested in it.
def branches(lines, lo, hi, name=None):
    covered = total = 0
    for line in lines:
        if lo <= line["line_number"] < hi and (name is None or decides(name, line["line_number"])):
            for b in line.get("branches", []):
                total += 1
                covered += b["count"] > 0
    return covered, total

# A line that decides: an if, a loop, a switch, a conditional expression or a short-circuit
# operator in its code (not its comment). gcov also gives branches to lines that decide nothing
# in the source: the compiler's, inlined from the standard library (a shared_ptr's reference
# count, an optional's destructor, a static's guard).
source_cache = {}
def source_line(name, number):
    if name not in source_cache:
        try:
            source_cache[name] = open(os.path.join(root, name), encoding="utf-8").read().splitlines()
        except OSError:
            source_cache[name] = []
    lines = source_cache[name]
    return lines[number - 1].strip() if 0 < number <= len(lines) else ""

def decides(name, number):
    code = source_line(name, number).split("//", 1)[0]
    return re.search(r"\b(if|for|while|switch|case|default)\b|\?|&&|\|\|", code) is not None

def is_generator(name):
    return "ValueSource&" in name or re.search(r"(^|::|\s)generate\w*\(", name) is not None

def missed(name, lines, lo, hi):
    for line in lines:
        if lo <= line["line_number"] < hi:
            n = sum(b["count"] == 0 for b in line.get("branches", []))
            if n:
                missed_rows.append((name, line["line_number"], n, len(line["branches"])))

gen_rows = ["| file | generator functions | branches | on lines that decide |", "|---|---|---:|---:|"]
kind_rows = []
missed_rows = []
for f in sorted(detail["files"], key=lambda f: rel(f["file"])):
    name = rel(f["file"])
    lines = f["lines"]
    if name.startswith("src/harness/generation/"):
        c, t = branches(lines, 0, 1 << 30)
        dc, dt = branches(lines, 0, 1 << 30, name)
        missed(name, lines, 0, 1 << 30)
        gen_rows.append(f"| `{name}` | whole file | {cell(c, t)} | {cell(dc, dt)} |")
    elif name.startswith("src/harness/kinds/") and name.endswith(".cpp"):
        funcs = sorted({(fn["lineno"], fn["name"]) for fn in f.get("functions", [])})
        picked, c, t, dc, dt = [], 0, 0, 0, 0
        for i, (start, fname) in enumerate(funcs):
            if not is_generator(fname) or any(fname.startswith(p + "::") for _, p in funcs if p != fname and is_generator(p)):
                continue
            end = next((s for s, n2 in funcs[i + 1:] if s > start and not n2.startswith(fname + "::")), 1 << 30)
            fc, ft = branches(lines, start, end)
            fdc, fdt = branches(lines, start, end, name)
            dc += fdc; dt += fdt
            missed(name, lines, start, end)
            short = fname.split("(anonymous namespace)::")[-1].replace("cc::harness::", "")
            depth = 0  # the name without its parameters: up to the first '(' outside <...>
            for k, ch in enumerate(short):
                depth += (ch == "<") - (ch == ">")
                if ch == "(" and depth == 0:
                    short = short[:k]; break
            picked.append(short); c += fc; t += ft
        if picked:
            kind_rows.append(f"| `{name}` | {', '.join(f'`{p}`' for p in sorted(set(picked)))} | {cell(c, t)} | {cell(dc, dt)} |")
gen_rows += kind_rows

# The branches of those rows not taken, each with its line; and the lines whose branches a marker
# leaves out of the count (GCOVR_EXCL_BR_LINE), each with the reason written beside it.
missed_lines = [f"- `{n}:{l}`: {m} of {t} not taken{'' if decides(n, l) else ' (the compiler’s: the line decides nothing)'}: `{source_line(n, l)}`"
                for n, l, m, t in sorted(set(missed_rows))]
marked_lines = []
for folder in ["src/harness/generation", "src/harness/kinds"]:
    for entry in sorted(os.listdir(os.path.join(root, folder))):
        name = f"{folder}/{entry}"
        for number, text in enumerate(open(os.path.join(root, name), encoding="utf-8").read().splitlines(), 1):
            if "GCOVR_EXCL" in text:
                code, _, reason = text.partition("// GCOVR_EXCL_BR_LINE")
                marked_lines.append(f"- `{name}:{number}`: `{code.strip()}`: {reason.lstrip(': ').strip()}")

cpu = "unknown"
try:
    for line in open("/proc/cpuinfo"):
        if line.startswith("model name"):
            cpu = line.split(":", 1)[1].strip(); break
except OSError:
    pass
commit = subprocess.run(["git", "-C", root, "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
dirty = subprocess.run(["git", "-C", root, "status", "--porcelain", "--", "src", "oracle", "tests", "include",
                        "CMakeLists.txt", "cmake"], capture_output=True, text=True).stdout.strip()
commit_text = f"`{commit}`" + (" (with uncommitted changes under src/, oracle/, tests/, include/ or cmake/)" if dirty else "")
label = os.environ["CC_LABEL"]
which = "every test" if label == "all" else f"the tests of label `{label}`"
if os.environ["CC_TESTS"]:
    which += f" whose names match `{os.environ['CC_TESTS']}`"
failed = [l.strip() for l in os.environ["CC_FAILED"].splitlines() if l.strip()]

page = f"""# Coverage

Generated by `bench/coverage.sh`; do not edit by hand.

- date: {datetime.datetime.now(datetime.timezone.utc).strftime('%Y-%m-%d %H:%M UTC')}
- commit: {commit_text}
- processor: {cpu}
- command: `{os.environ['CC_COMMAND']}`
- tests: {which}, {os.environ['CC_TEST_COUNT']} in all, {len(failed)} failed{': ' + '; '.join(failed) if failed else ''}
- build (`coverage` preset: {os.environ['CC_GCC']}, `-Og --coverage`; only what was out of date): {os.environ['CC_BUILD_SECONDS']} s; tests: {os.environ['CC_TEST_SECONDS']} s (nice, 2 jobs)
- {os.environ['CC_GCOVR']}, `--exclude-throw-branches --exclude-unreachable-branches`; the repository's
  sources only (not build/, tests/ or headers outside the repository). A folder counts the files
  compiled into the targets built in build/coverage, headers included; code run in a forked child
  that ends with `_Exit` writes no counters and shows as not covered. gcov counts a line's
  branches once per inlined copy and per template instantiation (src/collide's SIMD lane operators
  and kernels come in dozens of variants, one per kernel and parallel-slab pattern), so a folder's
  branch figure can sit far below its line figure.

## Per folder

{chr(10).join(folder_lines)}

## Generators

Branches of `src/harness/generation/` per file, and of the generator functions of each kind in
`src/harness/kinds/` (those that draw from a `ValueSource` or are named `generate*`, with the
lambdas inside them), reached by {which}: all that gcov counts, and those on lines that decide
(an `if`, a loop, a `switch`, `?:`, `&&` or `||` in the line's code). gcov gives branches to
lines that decide nothing in the source too: the compiler's, inlined from the standard library (a
`shared_ptr`'s reference count, an `optional`'s destructor, a static's guard).

{chr(10).join(gen_rows)}

Branches of those not taken ({len(missed_lines)} lines):

{chr(10).join(missed_lines) if missed_lines else "- none"}

Lines whose branches are left out of the count as defensive (a `GCOVR_EXCL_BR_LINE` marker, with
its reason; {len(marked_lines)} lines):

{chr(10).join(marked_lines) if marked_lines else "- none"}
"""
open(sys.argv[3], "w").write(page)
EOF

# The tables on the terminal, then the page.
sed -n '/^## Per folder/,$p' "$scratch/page.md"
if [ "$out" != - ]; then
  cp "$scratch/page.md" "$out"
  echo "coverage.sh: written to ${out#"$root"/}" >&2
fi
if [ "$test_status" -ne 0 ]; then
  echo "coverage.sh: ctest failed (status $test_status); the figures count the tests that ran" >&2
  exit 1
fi
