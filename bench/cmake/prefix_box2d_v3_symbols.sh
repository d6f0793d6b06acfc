#!/bin/sh
# Renames every global symbol a Box2D v3 static library defines to PREFIX<name>,
# in that library and in the adapter library that calls it, so two v3 builds
# (SSE2, AVX2) and Box2D 2.4.1 link into one binary without clashing.
#
#   prefix_box2d_v3_symbols.sh PREFIX NM OBJCOPY V3_LIB ADAPTER_LIB OUT_V3_LIB OUT_ADAPTER_LIB
set -eu
prefix=$1 nm=$2 objcopy=$3 v3_lib=$4 adapter_lib=$5 out_v3_lib=$6 out_adapter_lib=$7
map="$out_v3_lib.symbols"
"$nm" --defined-only --extern-only --format=posix "$v3_lib" |
  awk -v prefix="$prefix" 'NF >= 2 && $1 !~ /:$/ { print $1, prefix $1 }' | sort -u >"$map"
if [ ! -s "$map" ]; then
  echo "no symbols found in $v3_lib" >&2
  exit 1
fi
"$objcopy" --redefine-syms="$map" "$v3_lib" "$out_v3_lib"
"$objcopy" --redefine-syms="$map" "$adapter_lib" "$out_adapter_lib"
