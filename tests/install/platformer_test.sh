#!/bin/sh
# Runs examples/python/platformer.py against a real impulse-server (paused,
# on a free loopback port) and checks the game it played: the character
# stood on the terrain (ray casts), collected every coin (sensor events)
# and was told of its landings (hit events).
#
# usage: platformer_test.sh PYTHON SERVER SOURCE_DIR WORK_DIR
set -eu
python=$1 server=$2 source_dir=$3 work=$4
. "$(dirname "$0")/paused_server.sh"
start_paused_server "$server" "$work"
PATH="$(dirname "$(command -v protoc)"):$PATH" \
  "$python" "$source_dir/examples/python/platformer.py" --connect "127.0.0.1:$port" | tee "$work/out.txt"
[ "$(grep -c ': coin [0-9]* at .* collected$' "$work/out.txt")" -eq 3 ]
grep -Eq '^tick [0-9]+: landed at [0-9.]+ m/s' "$work/out.txt"
grep -Eq '^after 480 ticks: character at \((3[0-9]|4[0-9])\.[0-9], [0-9.]+\), on the ground [0-9]+ ticks, coins 3 of 3$' \
  "$work/out.txt"
echo "ok: the platformer walked, jumped the gap and collected every coin"
