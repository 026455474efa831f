#!/bin/bash -eu
# ClusterFuzzLite's (and OSS-Fuzz's) build: crosscheck's fuzz targets into $OUT, each with its
# seed corpus (fuzz_<name>_seed_corpus.zip), its dictionary (fuzz_<name>.dict) and its options
# (fuzz_<name>.options). Run by the base image with $CC, $CXX, $CFLAGS, $CXXFLAGS, $SRC, $OUT,
# $WORK and $LIB_FUZZING_ENGINE set; ctest's fuzz.clusterfuzzlite_build runs it the same way
# without Docker, against Debian's packages.
#
# The dependencies the image clones into $SRC (Dockerfile) are built first with the fuzzing
# flags; one that is not there is taken from the system.
deps=$WORK/deps
export PKG_CONFIG_PATH="$deps/lib/pkgconfig:$deps/share/pkgconfig${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
build() {  # source dir, build dir, extra CMake arguments (a later -DCMAKE_BUILD_TYPE wins)...
  local src=$1 dir=$2
  shift 2
  cmake -S "$src" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$deps" \
    -DCMAKE_PREFIX_PATH="$deps" -DBUILD_SHARED_LIBS=OFF "$@"
  cmake --build "$dir"
  cmake --install "$dir"
}
dependency() {  # name, extra CMake arguments...: built when the image cloned it
  local name=$1
  shift
  if [ -d "$SRC/$name" ]; then build "$SRC/$name" "$WORK/$name" "$@"; fi
}
dependency eigen -DBUILD_TESTING=OFF
dependency json -DJSON_BuildTests=OFF
dependency libccd -DENABLE_DOUBLE_PRECISION=ON -DBUILD_TESTING=OFF
dependency fcl -DFCL_STATIC_LIBRARY=ON -DFCL_WITH_OCTOMAP=OFF -DFCL_BUILD_TESTS=OFF
dependency bullet3 -DUSE_DOUBLE_PRECISION=ON -DBUILD_UNIT_TESTS=OFF -DBUILD_CPU_DEMOS=OFF -DBUILD_OPENGL3_DEMOS=OFF \
  -DBUILD_BULLET2_DEMOS=OFF -DBUILD_EXTRAS=OFF -DINSTALL_LIBS=ON
if [ -d "$SRC/bullet3" ] && [ ! -f "$deps/lib/pkgconfig/bullet-float64.pc" ]; then
  # Debian names the double-precision Bullet bullet-float64; the source build calls it bullet.
  sed 's/^Name: bullet/Name: bullet-float64/' "$deps/lib/pkgconfig/bullet.pc" > "$deps/lib/pkgconfig/bullet-float64.pc"
fi
cgal=()
if [ -d "$SRC/cgal" ]; then cgal=(-DCGAL_DIR="$SRC/cgal"); fi

# crosscheck itself with the fuzzing flags alone (build type None: no -O3 over the image's -O1,
# and its assertions kept).
build "$SRC/crosscheck" "$WORK/crosscheck" -DCMAKE_BUILD_TYPE=None -DCROSSCHECK_LIBFUZZER=ON -DCROSSCHECK_BUILD_TESTS=OFF \
  -DCROSSCHECK_BUILD_TOOL=OFF -DCROSSCHECK_FUZZ_ENGINE="$LIB_FUZZING_ENGINE" "${cgal[@]}"

# Every target the build lists (fuzz/CMakeLists.txt writes fuzz/<target>.seeds: its seed folders
# and files, one per line).
for seeds in "$WORK"/crosscheck/fuzz/fuzz_*.seeds; do
  target=$(basename "$seeds" .seeds)
  name=${target#fuzz_}
  cp "$WORK/crosscheck/fuzz/$target" "$OUT/"
  cp "$WORK/crosscheck/fuzz/$name.dict" "$OUT/$target.dict"
  printf '[libfuzzer]\ndict = %s.dict\ntimeout = 25\nrss_limit_mb = 2560\n' "$target" > "$OUT/$target.options"
  rm -f "$OUT/${target}_seed_corpus.zip"
  while IFS= read -r path; do
    [ -n "$path" ] || continue
    if [ -d "$path" ]; then
      (cd "$path" && zip -q -r "$OUT/${target}_seed_corpus.zip" .)
    else
      zip -q -j "$OUT/${target}_seed_corpus.zip" "$path"
    fi
  done < "$seeds"
done
