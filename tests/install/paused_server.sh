# Sourced by the example tests: start_paused_server SERVER WORK_DIR starts
# impulse-server paused on a free loopback port, logging into WORK_DIR (made
# afresh), stops it when the test exits, and sets $port.
start_paused_server() {
  rm -rf "$2"
  mkdir -p "$2"
  "$1" --port 0 --paused >"$2/server.out" 2>"$2/server.log" &
  server_pid=$!
  trap 'kill $server_pid 2>/dev/null || true' EXIT
  for _ in $(seq 50); do
    [ -s "$2/server.out" ] && break
    sleep 0.1
  done
  port=$(head -1 "$2/server.out" | sed 's/.*://')
}
