#!/bin/sh
# The order of src/harness's folders, as docs/design.md states it, held by the include lines:
# a folder includes only itself and the folders before it in the page's numbered list (under
# "## The order of the harness's folders"), except the includes its "Known exceptions" table
# lists. Fails naming each include that runs against the order and is not listed, each listed
# exception that no longer exists (the table must say what is), and each folder of src/harness
# the list leaves out.
# Usage: include_order.sh ROOT
set -u
root=$1
page="$root/docs/design.md"
[ -f "$page" ] || { echo "include_order.sh: no $page"; exit 1; }

# The numbered list: "N. `folder`", in the section on the order.
order=$(awk '/^## The order of the harness/ { on = 1; next } on && /^## / { exit }
  on && /^[0-9]+\. `[a-z_]+`/ { gsub(/^[0-9]+\. `|`.*$/, ""); print }' "$page")
[ -n "$order" ] || { echo "$page: no numbered list of folders under \"## The order of the harness's folders\""; exit 1; }
# The exceptions: "| `src/harness/FILE` | `harness/FILE` | ..." rows.
exceptions=$(awk '/^## The order of the harness/ { on = 1; next } on && /^## / { exit }
  on && /^\| `src\/harness\/[^`]*` \| `harness\/[^`]*` \|/ {
    split($0, cell, "`"); print cell[2] " " cell[4] }' "$page")

rank() {  # the position of folder $1 in the list, or 0
  printf '%s\n' "$order" | awk -v f="$1" '$0 == f { print NR; found = 1 } END { if (!found) print 0 }'
}

status=0
for dir in "$root"/src/harness/*/; do
  folder=$(basename "$dir")
  [ "$(rank "$folder")" -gt 0 ] || { echo "$page: src/harness/$folder is not in the order"; status=1; }
done

found=""
for file in $(cd "$root" && find src/harness -name '*.h' -o -name '*.cpp' | sort); do
  from=$(printf '%s\n' "$file" | cut -d/ -f3)
  from_rank=$(rank "$from")
  for target in $(sed -n 's/^#include "\(harness\/[a-z_]*\/[^"]*\)".*/\1/p' "$root/$file"); do
    to=$(printf '%s\n' "$target" | cut -d/ -f2)
    [ "$to" = "$from" ] && continue
    to_rank=$(rank "$to")
    [ "$to_rank" -lt "$from_rank" ] && [ "$to_rank" -gt 0 ] && continue
    found="$found$file $target
"
    if printf '%s\n' "$exceptions" | grep -qxF "$file $target"; then continue; fi
    echo "$file includes $target: $from may include only the folders before it in docs/design.md"
    status=1
  done
done

printf '%s\n' "$exceptions" | while read -r file target; do
  [ -n "$file" ] || continue
  printf '%s' "$found" | grep -qxF "$file $target" ||
    { echo "docs/design.md lists $file including $target as an exception, but it does not (take the row out)"; exit 1; }
done || status=1

if [ $status -ne 0 ]; then
  echo "include_order.sh: the includes above run against the order of docs/design.md"
  exit 1
fi
count=$(printf '%s' "$found" | grep -c . || true)
echo "src/harness: $(printf '%s\n' "$order" | tr '\n' ' ')in order; $count includes against it, each listed in docs/design.md"
