#!/bin/sh
# Every crosscheck command line of the manual (README.md and docs/*.md, in fenced code blocks),
# checked against the tool: its subcommand must exist and each flag it uses must be one that
# `crosscheck SUBCOMMAND --help` lists. A line ending with a backslash goes on to the next one;
# a command ends at a pipe, a redirection, `;`, `&&`, `||` or a comment; `[--flag VALUE]` and `...`
# are read as usage notation. Prints each command checked with its file and line, and fails naming
# the file, the line and the word of every unknown subcommand or flag.
# Usage: doc_flags.sh CROSSCHECK ROOT
set -u
tool=$1 root=$2
scratch=$(mktemp -d) || exit 1
trap 'rm -rf "$scratch"' EXIT

# One line per command: FILE:LINE SUBCOMMAND FLAG...  (SUBCOMMAND "-" when there is none).
for doc in "$root/README.md" "$root"/docs/*.md; do
  [ -f "$doc" ] || continue
  awk -v doc="${doc#"$root"/}" '
    /^[ \t]*```/ { inside = !inside; joined = ""; next }
    !inside { next }
    {
      line = $0
      if (joined == "") start = FNR
      if (line ~ /\\$/) { joined = joined substr(line, 1, length(line) - 1) " "; next }
      text = joined line
      joined = ""
      n = split(text, w, /[ \t]+/)
      for (i = 1; i <= n; ++i) {
        if (w[i] != "crosscheck" && w[i] !~ /\/crosscheck$/) continue
        out = doc ":" start
        sub_ = "-"
        for (j = i + 1; j <= n; ++j) {
          t = w[j]
          if (t ~ /^(\||\|\||&&|;|#)/ || t ~ /^[0-9]*[<>]/ || t ~ /^\)/) break
          gsub(/^\[+|\]+$|\.\.\.$/, "", t)
          if (t == "") continue
          if (sub_ == "-" && j == i + 1 && t !~ /^-/) { sub_ = t; continue }
          if (t ~ /^--?[A-Za-z]/) { sub(/=.*/, "", t); out = out " " t }
        }
        printf "%s %s", doc ":" start, sub_
        m = split(out, f, " ")
        for (k = 2; k <= m; ++k) printf " %s", f[k]
        printf "\n"
      }
    }' "$doc" 2>/dev/null
done >"$scratch/commands"

[ -s "$scratch/commands" ] || { echo "doc_flags.sh: no crosscheck command found in $root/README.md or $root/docs/"; exit 1; }

status=0
count=0
while read -r place subcommand flags; do
  count=$((count + 1))
  help="$scratch/help.$subcommand"
  if [ ! -f "$help" ]; then
    if [ "$subcommand" = - ]; then
      "$tool" --help >"$help" 2>&1 || { echo "$place: crosscheck --help failed"; status=1; continue; }
    elif ! "$tool" "$subcommand" --help >"$help" 2>&1; then
      echo "$place: crosscheck has no subcommand \"$subcommand\""
      : >"$help.unknown"
      status=1
      continue
    fi
  fi
  [ -f "$help.unknown" ] && { echo "$place: crosscheck has no subcommand \"$subcommand\""; status=1; continue; }
  for flag in $flags; do
    if ! grep -Eq -- "(^|[ ,])$flag([ ,]|$)" "$help"; then
      echo "$place: crosscheck ${subcommand#-} has no flag $flag"
      status=1
    fi
  done
done <"$scratch/commands"
echo "$count crosscheck command lines of the manual checked against the tool's own --help"
exit $status
