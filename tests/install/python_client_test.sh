#!/bin/sh
# Runs examples/python/impulse_client.py against a real impulse-server
# (paused, on a free loopback port) and checks what it printed.
#
# usage: python_client_test.sh PYTHON SERVER SOURCE_DIR WORK_DIR
set -eu
python=$1 server=$2 source_dir=$3 work=$4
. "$(dirname "$0")/paused_server.sh"
start_paused_server "$server" "$work"
echo "server pid $server_pid on port $port"
PATH="$(dirname "$(command -v protoc)"):$PATH" \
  "$python" "$source_dir/examples/python/impulse_client.py" --connect "127.0.0.1:$port" | tee "$work/out.txt"
grep -q '^welcome: client 1, 60 Hz, tick 0, admin True$' "$work/out.txt"
grep -q '^spawned: ball 4, box 5$' "$work/out.txt"
grep -q "^refused: ok=False error='circle: circle radius is outside the supported range" "$work/out.txt"
grep -q '^stepped: tick 120, state hash [0-9a-f]\{16\}$' "$work/out.txt"
grep -Eq '^ball: position \(5\.000, [0-9.]+\) m, .*mass 157\.1 kg' "$work/out.txt"
grep -Eq '^box: position .* mass 700\.0 kg' "$work/out.txt"
grep -q '^pong: tick 120, 5 bodies, 1 clients$' "$work/out.txt"
echo "ok: the Python client scripted the server"
