#!/bin/bash -eu
# Builds the dependencies with the fuzzing flags, then crosscheck's fuzz targets (no tests, no
# tool), and puts each target with its dictionary and seed corpus into $OUT.
deps=$WORK/deps
export PKG_CONFIG_PATH="$deps/lib/pkgconfig:$deps/share/pkgconfig"
build() {  # source dir, build dir, extra CMake arguments...
  local src=$1 dir=$2
  shift 2
  cmake -S "$src" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$deps" \
    -DCMAKE_PREFIX_PATH="$deps" -DBUILD_SHARED_LIBS=OFF "$@"
  cmake --build "$dir"
  cmake --install "$dir"
}
build "$SRC/eigen" "$WORK/eigen" -DBUILD_TESTING=OFF
build "$SRC/json" "$WORK/json" -DJSON_BuildTests=OFF
build "$SRC/libccd" "$WORK/libccd" -DENABLE_DOUBLE_PRECISION=ON -DBUILD_TESTING=OFF
build "$SRC/fcl" "$WORK/fcl" -DFCL_STATIC_LIBRARY=ON -DFCL_WITH_OCTOMAP=OFF -DFCL_BUILD_TESTS=OFF
build "$SRC/crosscheck" "$WORK/crosscheck" -DCROSSCHECK_LIBFUZZER=ON -DCROSSCHECK_BUILD_TESTS=OFF \
  -DCROSSCHECK_BUILD_TOOL=OFF -DCROSSCHECK_FUZZ_ENGINE="$LIB_FUZZING_ENGINE"

for target in "$WORK"/crosscheck/fuzz/fuzz_*; do
  [ -x "$target" ] || continue
  query=${target##*/fuzz_}
  cp "$target" "$OUT/"
  cp "$WORK/crosscheck/fuzz/$query.dict" "$OUT/fuzz_$query.dict"
  (cd "$SRC/crosscheck/corpora/$query/seed" && zip -q -r "$OUT/fuzz_${query}_seed_corpus.zip" .)
done
