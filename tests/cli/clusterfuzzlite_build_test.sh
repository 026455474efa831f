#!/bin/sh
# .clusterfuzzlite/build.sh as ClusterFuzzLite's base image runs it, without Docker and against
# Debian's FCL, Bullet and the rest: $CC, $CXX, $CFLAGS, $CXXFLAGS (the image's AddressSanitizer
# flags, less its -stdlib=libc++, which Debian's libraries are not built with), $SRC (holding the
# repository as crosscheck), $OUT, $WORK and $LIB_FUZZING_ENGINE. Then $OUT must hold every target
# (the registry's kinds and the two readers) with its seed corpus zip, dictionary and options
# file, and a target must fuzz. $WORK is kept between runs (an incremental build); the list of
# files in $OUT is left in WORK/out.txt.
# Usage: clusterfuzzlite_build_test.sh SOURCE_ROOT TARGETS_TXT WORK
set -u
root=$1 targets_txt=$2 work=$3
fail() { echo "clusterfuzzlite build: $*" >&2; exit 1; }
mkdir -p "$work/src" "$work/work" || fail "cannot make $work"
rm -rf "$work/out" && mkdir "$work/out" || fail "cannot make $work/out"
ln -sfn "$root" "$work/src/crosscheck" || fail "cannot link the source"
cp "$root/.clusterfuzzlite/build.sh" "$work/src/build.sh" || fail "cannot copy build.sh"
flags="-O1 -fno-omit-frame-pointer -gline-tables-only -DFUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION -fsanitize=address -fsanitize-address-use-after-scope -fsanitize=fuzzer-no-link"
start=$(date +%s)
( cd "$work/src" && env CC=clang-14 CXX=clang++-14 CFLAGS="$flags" CXXFLAGS="$flags" LIB_FUZZING_ENGINE=-fsanitize=fuzzer \
    SRC="$work/src" OUT="$work/out" WORK="$work/work" SANITIZER=address FUZZING_ENGINE=libfuzzer ARCHITECTURE=x86_64 \
    bash -eu build.sh ) > "$work/build.log" 2>&1 || fail "build.sh failed (see $work/build.log)"
seconds=$(( $(date +%s) - start ))
targets=0
for name in $(cat "$targets_txt") case_file obj_file; do
  t="$work/out/fuzz_$name"
  [ -x "$t" ] || fail "no target $t"
  [ -s "$t.dict" ] || fail "no dictionary $t.dict"
  grep -qx "dict = fuzz_$name.dict" "$t.options" || fail "$t.options does not name its dictionary"
  [ "$(unzip -Z1 "${t}_seed_corpus.zip" 2>/dev/null | grep -vc '/$')" -ge 1 ] || fail "no seeds in ${t}_seed_corpus.zip"
  targets=$((targets + 1))
done
[ "$targets" -ge 20 ] || fail "only $targets targets"
# A target fuzzes: libFuzzer's own main, over its unzipped seeds and 2000 inputs of its own.
rm -rf "$work/seeds" && mkdir "$work/seeds" && unzip -q "$work/out/fuzz_obb_obb_seed_corpus.zip" -d "$work/seeds" ||
  fail "cannot unzip the seeds"
"$work/out/fuzz_obb_obb" -runs=$(( $(ls "$work/seeds" | wc -l) + 2000 )) -dict="$work/out/fuzz_obb_obb.dict" "$work/seeds" > "$work/fuzz.log" 2>&1 ||
  fail "fuzz_obb_obb failed (see $work/fuzz.log)"
grep -q "INITED cov: [1-9]" "$work/fuzz.log" && grep -q "^Done [0-9]* runs" "$work/fuzz.log" ||
  fail "fuzz_obb_obb did not fuzz (see $work/fuzz.log)"
(cd "$work/out" && ls -l) > "$work/out.txt"
echo "clusterfuzzlite build: $targets targets in $work/out ($(ls "$work/out" | wc -l) files) in ${seconds}s"
