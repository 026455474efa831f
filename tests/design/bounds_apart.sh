#!/bin/sh
# The certified bounds stay apart (docs/design.md, "A test's certified bound"): a test's bound
# lives in its own src/collide/*_bound.h, which includes no other test's bound (the shared
# pieces aside: widening.h, the quotients' widening, and transform_bound.h, apply()'s rounding);
# record_sink.h includes nothing of the library; and bound_records.h,
# which gathers every bound, is included by no header and, in the library, by bound_records.cpp
# alone, so that a change to one bound recompiles that test and the readers of the records only.
# Usage: bounds_apart.sh ROOT
set -u
root=$1
status=0
cd "$root/src/collide" || exit 1
for file in *_bound.h; do
  for target in $(sed -n 's/^#include "collide\/\([^"]*\)".*/\1/p' "$file"); do
    case $target in
      transform_bound.h) ;;
      *_bound.h | bound_records.h)
        echo "src/collide/$file includes $target: a test's bound includes no other test's bound, nor the records"
        status=1 ;;
    esac
  done
done
if grep -q '^#include "collide/' record_sink.h; then
  echo "src/collide/record_sink.h includes a library header: every primitive includes it"
  status=1
fi
for file in $(cd "$root" && grep -rl '^#include "collide/bound_records.h"' src oracle tests bench fuzz 2>/dev/null); do
  case $file in
    *.h) echo "$file includes collide/bound_records.h: only source files may (it reaches every test's bound)"; status=1 ;;
    src/collide/bound_records.cpp) ;;
    src/collide/* | src/harness/kinds/*)
      echo "$file includes collide/bound_records.h: a test or a probe needs its own bound only"
      status=1 ;;
  esac
done
[ $status -eq 0 ] && echo "src/collide: $(ls *_bound.h | wc -l) bounds apart; bound_records.h in no header"
exit $status
