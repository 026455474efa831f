#!/bin/sh
# Runs, verbatim and in order, every command of the first ```sh block after the heading HEADING
# of the document DOC, from the folder ROOT, as a reader pastes them. A command's trailing
# comment "# exits N" gives its exit status (0 without one). Fails on the first command that
# exits otherwise, showing its output. Usage: doc_commands.sh DOC HEADING ROOT
set -u
doc=$1 heading=$2 root=$3
block=$(awk -v heading="$heading" '
  $0 == heading { seen = 1; next }
  seen && !inside && /^```sh$/ { inside = 1; next }
  inside && /^```$/ { exit }
  inside { print }' "$doc")
[ -n "$block" ] || { echo "$doc: no sh block after \"$heading\""; exit 1; }
cd "$root" || exit 1
count=0
while IFS= read -r line; do
  case "$line" in ""|"#"*) continue ;; esac
  expected=$(printf '%s\n' "$line" | sed -n 's/.*# exits \([0-9][0-9]*\).*/\1/p')
  [ -n "$expected" ] || expected=0
  echo "\$ $line"
  output=$(sh -c "$line" 2>&1 </dev/null)
  status=$?
  if [ "$status" -ne "$expected" ]; then
    printf '%s\n' "$output" | tail -n 40
    echo "$doc: exit status $status, the document says $expected"
    exit 1
  fi
  count=$((count + 1))
done <<BLOCK
$block
BLOCK
echo "$count commands of $doc ran as written"
