#!/usr/bin/env bash
# Edge polling benchmark (BENCHMARKS.md, "Edge polling"; not a test): for 100, 1,000 and 10,000 robots,
# robot-sim runs as a separate process on this machine and the edge (eu.brain.iot.edge.impl.Edge, no framework)
# polls every robot and door every 500 ms; prints polls/s, the share on time, CPU of both processes, load average.
# Usage: edge/bench/poll-bench.sh [options]        (--help lists them; from any directory)
# Env: SKIP_BUILD=1 reuses the last build; JAVA_OPTS adds JVM options for the edge's JVM, e.g.
#      JAVA_OPTS="-XX:StartFlightRecording=filename=/tmp/edge.jfr,settings=profile"
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
cd "$root"
cp_file=edge/edge-impl/target/bench-classpath.txt
for a in "$@"; do
  [ "$a" = --help ] || [ "$a" = -h ] && SKIP_BUILD="${SKIP_BUILD:-$( [ -f "$cp_file" ] && echo 1 || echo 0)}"
done
if [ "${SKIP_BUILD:-0}" != 1 ] || [ ! -f "$cp_file" ] || [ ! -f robot-sim/target/robot-sim.jar ]; then
  echo "building the edge, its test classes and robot-sim (mvn -B -q -pl edge/edge-impl -am package -DskipTests) ..." >&2
  mvn -B -q -pl edge/edge-impl -am package -DskipTests dependency:build-classpath \
    -Dmdep.outputFile=target/bench-classpath.txt -Dmdep.includeScope=test
fi
# shellcheck disable=SC2086
exec java ${JAVA_OPTS:-} -cp "edge/edge-impl/target/test-classes:edge/edge-impl/target/classes:$(cat "$cp_file")" \
  eu.brain.iot.edge.impl.PollBenchmark --sim-jar robot-sim/target/robot-sim.jar "$@"
