#!/usr/bin/env bash
# Poll benchmark of the robot simulator: 10,000 robots served by one robot-sim process, polled by PollLoad
# (asynchronous Netty client, keep-alive connections) on the same machine.
# Usage: benchmarks/bench/poll-load.sh [PollLoad options...]
#   after `mvn -B -q -pl robot-sim,benchmarks -am package -DskipTests` from the repository root
# Env: PORT (default 18090), SERVER=netty|jdk (jdk = the com.sun.net.httpserver baseline), JDK_THREADS (default 2).
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
sim="$root/robot-sim/target/robot-sim.jar"
bench="$root/benchmarks/target/benchmarks.jar"
out="$root/benchmarks/target"
map="$out/bench-10000-robots.map"
port="${PORT:-18090}"
server="${SERVER:-netty}"
for jar in "$sim" "$bench"; do
  [ -f "$jar" ] || { echo "no $jar: run 'mvn -B -q -pl robot-sim,benchmarks -am package -DskipTests' first" >&2; exit 1; }
done

echo "machine: $(nproc) cores, $(java -version 2>&1 | head -1), load average $(cut -d' ' -f1-3 /proc/loadavg)"
if [ "$server" = jdk ]; then
  # sun.net.httpserver.nodelay: without it the JDK server stalls ~40 ms per answer (Nagle + delayed ACK)
  java -Dsun.net.httpserver.nodelay=true -cp "$bench" eu.brain.iot.benchmarks.robotsim.JdkServerBaseline \
    --port "$port" --robots 10000 --threads "${JDK_THREADS:-2}" > "$out/bench-server.log" 2>&1 &
else
  java -jar "$sim" generate --robots 10000 --carts 2000 --width 400 --height 150 --out "$map"
  java -jar "$sim" --port "$port" --map "$map" --quiet > "$out/bench-server.log" 2>&1 &
fi
server_pid=$!
trap 'kill "$server_pid" 2>/dev/null || true' EXIT
for _ in $(seq 1 100); do
  curl -sf "http://127.0.0.1:$port/" > /dev/null && break
  sleep 0.2
done
java -cp "$bench" eu.brain.iot.benchmarks.robotsim.PollLoad --url "http://127.0.0.1:$port/" "$@"
