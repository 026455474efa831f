#!/bin/sh
# A fuzz target's impl_bugs abort from a function of their own group (fuzz/impl_bug_groups.h), so
# that a service grouping crashes by stack keeps them apart: two subjects wrong in two ways are
# run through fuzz_aabb_aabb (the replay build) under gdb, and each backtrace must hold its
# group's function, which `crosscheck fuzz-case` names for the same input; every group's
# function is a symbol of its own (none folded into another).
# Usage: fuzz_crash_groups_test.sh CROSSCHECK FUZZ_DIR SUBJECTS_DIR WORK
set -u
tool=$1 fuzz=$2 subjects=$3 work=$4
fail() { echo "fuzz crash groups: $*" >&2; exit 1; }
command -v gdb > /dev/null || fail "gdb is not installed (./.ci/deps installs it)"
rm -rf "$work" && mkdir -p "$work" || fail "cannot make $work"
target="$fuzz/fuzz_aabb_aabb"

# aabb_aabb records (harness/formats/fuzz_record.h): the tag (kind 2), then a's lo and hi, b's lo and hi.
record() { /usr/bin/python3 -c 'import struct, sys
sys.stdout.buffer.write(bytes([2]) + struct.pack("<12d", *map(float, sys.argv[1:])))' "$@"; }
record 0 0 0 1 1 1 1 0 0 2 1 1 > "$work/touching" || fail "cannot write a record"
record 0.25 0 0 1 1 1 0 0 0 2 1 1 > "$work/crashing" || fail "cannot write a record"

# The input, the subject, and the group it must abort in.
check() {
  input=$1 subject=$2 group=$3
  function=impl_bug_$(echo "$group" | tr . _)
  CROSSCHECK_SUBJECT="$subjects/$subject" gdb -batch -nx -ex run -ex bt --args "$target" "$work/$input" \
    > "$work/$input.gdb" 2>&1
  grep -q "received signal SIGABRT" "$work/$input.gdb" || fail "$input with $subject did not abort (see $work/$input.gdb)"
  grep -q "impl_bug group $group\$" "$work/$input.gdb" || fail "$input with $subject: no \"impl_bug group $group\" (see $work/$input.gdb)"
  # The group's function is on the stack, right above abort().
  sed -n '/^#[0-9]/p' "$work/$input.gdb" | grep -A1 'abort ()' | grep -q "$function" ||
    fail "$input with $subject: $function is not the frame above abort() (see $work/$input.gdb)"
  line=$("$tool" fuzz-case aabb_aabb "$work/$input" --out "$work/cases" --subject "$subjects/$subject") ||
    fail "fuzz-case $input with $subject failed"
  [ "$(echo "$line" | awk '{print $2, $4}')" = "impl_bug $group" ] || fail "fuzz-case names another group: $line"
}
check touching libtest_subject_hostile_wrong.so aabb_aabb.missed_touch
check crashing libtest_subject_misbehaving.so aabb_aabb.failed

# One function per kind and class of disagreement, each at an address of its own.
kinds=$(wc -w < "$fuzz/targets.txt")
functions=$(nm "$target" | grep -c 'impl_bug_[a-z_]*Ev$')
addresses=$(nm "$target" | grep 'impl_bug_[a-z_]*Ev$' | awk '{print $1}' | sort -u | wc -l)
[ "$functions" -eq $((kinds * 8)) ] || fail "$functions group functions for $kinds kinds and 8 classes"
[ "$addresses" -eq "$functions" ] || fail "$functions group functions at only $addresses addresses (some were folded)"
echo "fuzz crash groups: 2 groups apart on the stack, $functions functions at $addresses addresses"
