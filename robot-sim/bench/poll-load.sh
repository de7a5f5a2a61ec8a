#!/usr/bin/env bash
# Poll benchmark of the robot simulator (BENCHMARKS.md, "Robot simulator"): 10,000 robots served by one process,
# polled by `poll-load` (asynchronous Netty client, keep-alive connections) on the same machine.
# Usage: robot-sim/bench/poll-load.sh [poll-load options...]   (after `cd robot-sim && mvn -B -q package`)
# Env: PORT (default 18090), SERVER=netty|jdk (jdk = the com.sun.net.httpserver baseline), JDK_THREADS (default 2).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
jar="$here/target/robot-sim.jar"
map="$here/target/bench-10000-robots.map"
port="${PORT:-18090}"
server="${SERVER:-netty}"
[ -f "$jar" ] || { echo "no $jar: run 'mvn -B -q package' in robot-sim first" >&2; exit 1; }

echo "machine: $(nproc) cores, $(java -version 2>&1 | head -1), load average $(cut -d' ' -f1-3 /proc/loadavg)"
if [ "$server" = jdk ]; then
  # sun.net.httpserver.nodelay: without it the JDK server stalls ~40 ms per answer (Nagle + delayed ACK)
  java -Dsun.net.httpserver.nodelay=true -cp "$jar" eu.brain.iot.robotsim.load.JdkServerBaseline --port "$port" --robots 10000 \
    --threads "${JDK_THREADS:-2}" > "$here/target/bench-server.log" 2>&1 &
else
  java -jar "$jar" generate --robots 10000 --carts 2000 --width 400 --height 150 --out "$map"
  java -jar "$jar" --port "$port" --map "$map" --quiet > "$here/target/bench-server.log" 2>&1 &
fi
server_pid=$!
trap 'kill "$server_pid" 2>/dev/null || true' EXIT
for _ in $(seq 1 100); do
  curl -sf "http://127.0.0.1:$port/" > /dev/null && break
  sleep 0.2
done
java -jar "$jar" poll-load --url "http://127.0.0.1:$port/" "$@"
