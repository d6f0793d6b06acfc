#!/bin/sh
# Installs the engine from a build tree into a fresh prefix inside it, then
# builds examples/cpp against the installed package twice, through
# find_package(Impulse) and through pkg-config, runs both and checks what
# they print. Nothing outside BUILD_DIR/install-test is written.
#
# usage: install_and_consume.sh SOURCE_DIR BUILD_DIR CXX
set -eu
source_dir=$1 build_dir=$2 cxx=$3
work=$build_dir/install-test
prefix=$work/prefix
rm -rf "$work"
mkdir -p "$work"

echo "== cmake --install (engine only) into $prefix"
cmake --build "$build_dir" --target impulse_engine >/dev/null
cmake --install "$build_dir" --prefix "$prefix" >/dev/null
(cd "$prefix" && find . -type f | sort)
# The engine alone: one library, headers, the CMake package and impulse.pc.
libraries=$(cd "$prefix" && find . -name '*.a' -o -name '*.so*' | sort | tr '\n' ' ')
[ "$libraries" = "./lib/libimpulse_engine.a " ] || { echo "unexpected libraries: $libraries"; exit 1; }
if (cd "$prefix" && find .) | grep -Eiq 'server|client|viewer|sdl|proto'; then
  echo "the install holds more than the engine"; exit 1
fi

echo "== find_package(Impulse): configure and build examples/cpp"
cmake -S "$source_dir/examples/cpp" -B "$work/cmake-build" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_PREFIX_PATH="$prefix" >"$work/configure.log"
cmake --build "$work/cmake-build" >"$work/build.log"
"$work/cmake-build/drop" | tee "$work/cmake-run.txt"

echo "== pkg-config impulse: $(PKG_CONFIG_PATH=$prefix/lib/pkgconfig pkg-config --cflags --libs impulse)"
# shellcheck disable=SC2046
"$cxx" -O2 "$source_dir/examples/cpp/drop.cpp" -o "$work/drop-pkg-config" \
  $(PKG_CONFIG_PATH="$prefix/lib/pkgconfig" pkg-config --cflags --libs impulse)
"$work/drop-pkg-config" >"$work/pkg-config-run.txt"

# What the program printed: the refusal, three reports, a hash; the box at
# rest on the floor (its centre half its 1 m side above y = 0) and asleep.
grep -q '^refused: polygon needs at least 3 vertices$' "$work/cmake-run.txt"
[ "$(grep -c '^t = ' "$work/cmake-run.txt")" -eq 3 ]
last_box=$(grep '^  box' "$work/cmake-run.txt" | tail -1)
echo "$last_box" | grep -Eq ', +0\.(49|50|51)[0-9]\) m, .*asleep$' || { echo "box not at rest: $last_box"; exit 1; }
grep -q '^state hash [0-9a-f]\{16\}$' "$work/cmake-run.txt"
# Same engine, same program: both builds step bit-identically.
cmp "$work/cmake-run.txt" "$work/pkg-config-run.txt" || { echo "the two builds differ"; exit 1; }
echo "== ok: installed engine consumed through find_package and pkg-config, identical output"
