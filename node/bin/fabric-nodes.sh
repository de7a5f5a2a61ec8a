#!/usr/bin/env bash
# Starts a fabric of several nodes on this machine, joined through an MQTT 5 broker: the embedded broker
# (broker/target/broker.jar, started here in a process of its own) or any broker given by URI. ./fabric-node runs
# this script for --nodes=N and --broker=URI. See node/README.md, "A fabric of several nodes".
#
#   ./fabric-node --nodes=3                 the embedded broker on 127.0.0.1:1883 and node1..node3, REST on
#                                           127.0.0.1:8181..8183; runs until Ctrl-C (or SIGTERM), which stops them all
#   ./fabric-node --nodes=3 --fleet         the same, and the simulated fleet (robot-sim, started by node1's
#                                           ./fabric-node; --fleet-port=N as for one node), shared by the nodes: each
#                                           edge polls its share of the robots (share=K/N, the doors on node1), held
#                                           by a lease that the others take over when the node dies
#   ./fabric-node --nodes=2 --broker=tcp://127.0.0.1:1883   the nodes join that broker; none is started here
#   ./fabric-node --broker=URI              one node joined to that broker, with its interactive shell
#
# Options (besides those of ./fabric-node: -D... and -X... passed on to every node; --rebuild, the node built once):
#   --nodes=N           how many nodes, 1..20 (default 1)
#   --broker=URI        the broker the nodes join (tcp://HOST:PORT); without it the embedded broker starts here
#   --broker-port=N     the embedded broker's port (default 1883)
#   --fabric=NAME       the fabric's name, its topic tree's root (default: fabric)
#   --state=DIR         the fabric's folder: DIR/nodeK is node K's state (its configuration folder, log, journal),
#                       DIR/broker the embedded broker's, DIR/fabric.key the fabric's signing key
#                       (default ${XDG_STATE_HOME:-~/.local/state}/brain-iot/fabric)
#   --http-port=N       node K's REST port is N+K-1 (default 8181)
#   --name=NAME         the node's name when there is one node (default node1)
#   --no-shell          one node: no interactive shell (several nodes never have one)
#
# Each node gets the configuration PID eu.brain.iot.federation (a .cfg file in DIR/nodeK/config, beside copies of
# node/config's files): broker.uri, fabric.name, node.name, key.file, state.dir. The key file is created (32 random
# bytes, base64, mode 600) when missing; every node of a fabric must be given the same one.
#
# A fabric of several nodes is "ready" once every node has started (its levels up without problems: its REST API
# listening) and joined it; a node that does not (its key, a broker that does not take it) stops them all, its log's
# reason shown. Before anything is made or started, a broker given by URI must answer, and the embedded broker's port
# and every node's REST port must be free.
#
# Exit code: 130 after Ctrl-C, 143 after SIGTERM (every node stopped), 1 when a port is taken, the broker or a node
# did not start or join (its log is shown), or a node or the embedded broker ended (named, with its exit code),
# 2 for a bad command line.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
broker_jar="$root/broker/target/broker.jar"
max_nodes=20
ready_timeout_s=180
join_timeout_s=60
reach_grace_s=10

nodes=1
nodes_given=false
broker_uri=
broker_port=1883
fabric_name=fabric
state_dir="${XDG_STATE_HOME:-$HOME/.local/state}/brain-iot/fabric"
http_base=8181
single_name=
shell=true
fleet=false
fleet_port=8090
node_args=()
rebuild=false

die() { echo "fabric-nodes: $*" >&2; exit 2; }
port_arg() { # port_arg <flag> <value>: the value when it is a port 1..65535, else a usage error
  [[ $2 =~ ^[0-9]+$ ]] && (( $2 >= 1 && $2 <= 65535 )) || die "$1 needs a port 1..65535, found '$2'"
  echo "$2"
}

# value_example <option>: a value to show in the message for an option written without '='
value_example() {
  case "$1" in
    --nodes) echo 3 ;; --broker) echo tcp://127.0.0.1:1883 ;; --fabric|--name) echo NAME ;; --state) echo DIR ;;
    *) echo PORT ;;
  esac
}

for arg in "$@"; do
  case "$arg" in
    --nodes=*)
      nodes="${arg#--nodes=}"; nodes_given=true
      [[ $nodes =~ ^[0-9]+$ ]] && (( nodes >= 1 && nodes <= max_nodes )) \
        || die "--nodes needs a number of nodes 1..$max_nodes, found '$nodes'" ;;
    --broker=*)
      broker_uri="${arg#--broker=}"
      [[ $broker_uri =~ ^(tcp|mqtt|ssl|mqtts)://[^/:]+:([0-9]{1,5})/?$ ]] && (( BASH_REMATCH[2] <= 65535 )) \
        || die "--broker needs a broker URI with a port 1..65535, such as tcp://127.0.0.1:1883, found '$broker_uri'" ;;
    --broker-port=*) broker_port="$(port_arg --broker-port "${arg#--broker-port=}")" ;;
    --fabric=*)
      fabric_name="${arg#--fabric=}"
      [[ $fabric_name =~ ^[A-Za-z0-9_.-]{1,64}$ ]] \
        || die "--fabric needs a name of 1 to 64 letters, digits, '_', '.' or '-', found '$fabric_name'" ;;
    --state=*)
      state_dir="${arg#--state=}"; [[ -n $state_dir ]] || die "--state needs a folder" ;;
    --http-port=*) http_base="$(port_arg --http-port "${arg#--http-port=}")" ;;
    --name=*)
      single_name="${arg#--name=}"
      [[ $single_name =~ ^[A-Za-z0-9_.-]{1,64}$ ]] \
        || die "--name needs 1 to 64 letters, digits, '_', '.' or '-', found '$single_name'" ;;
    --no-shell) shell=false ;;
    --fleet) fleet=true ;;
    --fleet-port=*) fleet=true; fleet_port="$(port_arg --fleet-port "${arg#--fleet-port=}")" ;;
    --rebuild) rebuild=true ;;
    -D*|-X*) node_args+=("$arg") ;;
    --check) die "--check starts one node: use ./fabric-node --check without --nodes/--broker" ;;
    -h|--help) sed -n '2,/^[^#]/{/^#/!q;s/^# \{0,1\}//;p}' "$0"; exit 0 ;;
    --nodes|--broker|--broker-port|--fabric|--state|--http-port|--name|--fleet-port)
      die "$arg takes its value after '=', e.g. $arg=$(value_example "$arg")" ;;
    *) die "unknown argument '$arg' (try --help)" ;;
  esac
done
if [[ -n $single_name ]] && (( nodes > 1 )); then
  die "--name names one node; with --nodes=$nodes they are node1..node$nodes"
fi
(( http_base + nodes - 1 <= 65535 )) || die "--http-port=$http_base leaves no port for node $nodes"
$nodes_given || [[ -n $broker_uri ]] || die "give --nodes=N or --broker=URI"

# node_name <k>: node K's name (its folder is $state_dir/<name>)
node_name() { if [[ -n $single_name ]]; then echo "$single_name"; else echo "node$1"; fi; }

# answers <host> <port>: whether a program accepts connections there (within 3 s). Checked before anything is made
# or built (a first build takes minutes): a broker given by URI must answer; the ports this script has processes
# listen on (the embedded broker's, each node's REST port) must not.
answers() { timeout 3 bash -c 'exec 3<>"/dev/tcp/$0/$1"' "$1" "$2" 2>/dev/null; }

if [[ $broker_uri =~ ^[a-z]+://([^/:]+):([0-9]+) ]] && ! answers "${BASH_REMATCH[1]}" "${BASH_REMATCH[2]}"; then
  echo "fabric-nodes: nothing answers at ${BASH_REMATCH[1]}:${BASH_REMATCH[2]} (--broker=$broker_uri) within 3 s:" \
    "start the broker there, or leave --broker out for the embedded one" >&2
  exit 1
fi
if [[ -z $broker_uri ]] && answers 127.0.0.1 "$broker_port"; then
  echo "fabric-nodes: port $broker_port of 127.0.0.1 is taken (a broker already running?): join that broker" \
    "with --broker=tcp://127.0.0.1:$broker_port, or give the embedded broker another port with --broker-port=N" >&2
  exit 1
fi
# http_port_hint: what to do about a taken REST port
http_port_hint() {
  if (( nodes > 1 )); then
    echo "choose other ports with --http-port=N (node K gets N+K-1; now N is $http_base)"
  else
    echo "choose another with --http-port=N"
  fi
}

# every node's REST port (node K's is the --http-port plus K-1): a node on a taken one would run without its REST API
# and dashboard, and the port would lead to another program's
for k in $(seq 1 "$nodes"); do
  port=$((http_base + k - 1))
  if answers 127.0.0.1 "$port"; then
    echo "fabric-nodes: port $port of 127.0.0.1, for $(node_name "$k")'s REST API and dashboard, is taken (another" \
      "node or program listens there): $(http_port_hint)" >&2
    exit 1
  fi
done

mkdir -p "$state_dir"
state_dir="$(cd "$state_dir" && pwd)"

# The fabric's signing key: one file shared by every node of the fabric, never under the repository.
key_file="$state_dir/fabric.key"
if [[ ! -s $key_file ]]; then
  (umask 077 && head -c 32 /dev/urandom | base64 >"$key_file")
  echo "fabric-nodes: created the fabric's key $key_file (give every node of this fabric a copy)" >&2
fi

# configure_node <k> <broker uri>: node K's configuration folder, node/config's files and the federation's PID
configure_node() {
  local name dir
  name="$(node_name "$1")"; dir="$state_dir/$name/config"
  mkdir -p "$dir"
  find "$root/node/config" -maxdepth 1 -type f \( -name '*.cfg' -o -name '*.config' \) -exec cp {} "$dir"/ \;
  if $fleet && (( nodes > 1 )); then
    cat >"$dir/eu.brain.iot.edge.cfg" <<EOF
# Written by node/bin/fabric-nodes.sh at every start: this node's share of the fleet, leased (edge/README.md).
share=$1/$nodes
share.leased=true
doors.owner=1
EOF
    cat >"$dir/eu.brain.iot.federation.lease.cfg" <<EOF
# Written by node/bin/fabric-nodes.sh at every start: the device leases, their defaults (federation/README.md).
EOF
    cat >"$dir/eu.brain.iot.bms.cfg" <<EOF
# Written by node/bin/fabric-nodes.sh at every start: the robot behaviour of all nodes but one stands by, so the
# robot events that had it installed here wait for the interest of the one that drives the fleet (bms/README.md).
handover.grace.ms=10000
EOF
  else # a share written at an earlier start with --fleet goes; a file of the user's stays
    for f in "$dir/eu.brain.iot.edge.cfg" "$dir/eu.brain.iot.federation.lease.cfg" "$dir/eu.brain.iot.bms.cfg"; do
      if head -n 1 "$f" 2>/dev/null | grep -q '^# Written by node/bin/fabric-nodes.sh'; then rm -f "$f"; fi
    done
  fi
  cat >"$dir/eu.brain.iot.federation.cfg" <<EOF
# Written by node/bin/fabric-nodes.sh at every start: this node's membership in the fabric.
broker.uri=$2
fabric.name=$fabric_name
node.name=$name
key.file=$key_file
state.dir=$state_dir/$name/federation
EOF
}

# node_command <k>: ./fabric-node's arguments for node K. ./fabric-node's own --name/--state/--http-port are used
# when it has them; otherwise the framework properties they stand for.
node_command() {
  local k=$1 name port
  name="$(node_name "$k")"; port=$((http_base + k - 1))
  cmd=("$root/fabric-node")
  if grep -q -- '--state=\*' "$root/fabric-node"; then
    cmd+=("--name=$name" "--state=$state_dir/$name" "--http-port=$port")
  else
    cmd+=("-Dfabric.node.name=$name" "-Dorg.osgi.service.http.port=$port")
  fi
  cmd+=("-Dfelix.fileinstall.dir=$state_dir/$name/config")
  if $fleet; then
    if (( k == 1 )); then
      cmd+=("--fleet-port=$fleet_port") # node1's ./fabric-node starts robot-sim
    else
      cmd+=("-Deu.brain.iot.edge.fleet.url=http://127.0.0.1:$fleet_port/")
    fi
  fi
  cmd+=(${node_args[@]+"${node_args[@]}"})
}

# --- the broker -------------------------------------------------------------------------------------------------
broker_pid=
node_pids=()
stop_all() {
  local pid
  # a broker that ended already (kill -9) is not said to be stopped here
  [[ -n $broker_pid ]] && ! kill -0 "$broker_pid" 2>/dev/null && { wait "$broker_pid" 2>/dev/null; broker_pid=; }
  if [[ ${#node_pids[@]} -gt 0 || -n $broker_pid ]]; then
    echo "fabric-nodes: stopping ${#node_pids[@]} node(s)$( [[ -n $broker_pid ]] && echo " and the broker")" >&2
  fi
  for pid in ${node_pids[@]+"${node_pids[@]}"}; do kill -TERM "$pid" 2>/dev/null || true; done
  for pid in ${node_pids[@]+"${node_pids[@]}"}; do wait "$pid" 2>/dev/null || true; done
  if [[ -n $broker_pid ]]; then
    kill -TERM "$broker_pid" 2>/dev/null || true
    wait "$broker_pid" 2>/dev/null || true
  fi
  if [[ ${#node_pids[@]} -gt 0 || -n $broker_pid ]]; then
    echo "fabric-nodes: stopped" >&2
  fi
}

# await_line <pid> <log> <prefix> <what>: waits for a line starting with the prefix in the log, while the process
# lives, up to ready_timeout_s; on failure shows the log's end and exits 1
await_line() {
  local deadline=$((SECONDS + ready_timeout_s))
  until grep -q "^$3" "$2" 2>/dev/null; do
    if ! kill -0 "$1" 2>/dev/null || (( SECONDS >= deadline )); then
      kill -0 "$1" 2>/dev/null && reason="was not ready within $ready_timeout_s s" || reason="ended"
      echo "fabric-nodes: $4 $reason; the end of its log, $2:" >&2
      tail -n 30 "$2" | sed 's/^/  /' >&2
      exit 1
    fi
    sleep 0.1
  done
}

trap stop_all EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
trap 'exit 129' HUP
# SIGKILL "trapped" too: bash reports a background process killed by a signal the script does not trap in a line of
# its own ("line N: PID Killed java -jar ..."); this script names the process that ended and its exit code instead.
# The trap never runs: SIGKILL cannot be caught, nor ignored, by this script or its processes.
trap '' KILL

# The node (and robot-sim) built first, once, its progress shown: a node's ready time never includes a build.
build_args=(--build-only)
$rebuild && build_args+=(--rebuild)
$fleet && build_args+=(--fleet)
"$root/fabric-node" "${build_args[@]}" || { echo "fabric-nodes: the node's build failed (above)" >&2; exit 1; }

if [[ -z $broker_uri ]]; then
  newer=
  [[ -f $broker_jar ]] && newer="$(find "$root/broker/src/main" "$root/broker/pom.xml" "$root/pom.xml" \
    -newer "$broker_jar" -type f -print -quit)"
  if [[ ! -f $broker_jar || -n $newer ]]; then
    echo "fabric-nodes: building the embedded broker (mvn -B -pl broker package -DskipTests; log:" \
      "broker/target/broker-build.log) ..." >&2
    mkdir -p "$root/broker/target"
    (cd "$root" && mvn -B -pl broker package -DskipTests >"$root/broker/target/broker-build.log" 2>&1) || {
      echo "fabric-nodes: the broker's build failed; its errors (all of it: broker/target/broker-build.log):" >&2
      grep -a '^\[ERROR\]' "$root/broker/target/broker-build.log" | head -20 | sed 's/^/  /' >&2
      exit 1
    }
  fi
  broker_log="$state_dir/broker.log"
  # in memory: the fabric needs no broker persistence (each node keeps an event until the receiving node acknowledged
  # it, federation/README.md), and sessions in files doubled node-to-node latency (BENCHMARKS.md)
  java -jar "$broker_jar" --port "$broker_port" --data "$state_dir/broker" --in-memory >"$broker_log" 2>&1 </dev/null &
  broker_pid=$!
  await_line "$broker_pid" "$broker_log" "broker listening on " "the embedded broker (127.0.0.1:$broker_port)"
  broker_uri="tcp://127.0.0.1:$broker_port"
  echo "fabric-nodes: embedded broker $broker_uri (pid $broker_pid, log $broker_log)" >&2
fi

for k in $(seq 1 "$nodes"); do configure_node "$k" "$broker_uri"; done

# One node with a shell: the node runs in the foreground, reading the terminal; when it ends, the EXIT trap stops
# the broker if it was started here.
if (( nodes == 1 )) && $shell; then
  node_command 1
  set +e
  "${cmd[@]}"
  exit $?
fi

# --- the nodes, in the background ------------------------------------------------------------------------------
# All at once (built above), so that each takes its own share of a shared fleet within the device leases' join
# grace (federation/README.md, "Device leases"); with --fleet node1's ./fabric-node starts robot-sim.
start_node() {
  local name log
  name="$(node_name "$1")"; log="$state_dir/$name/node.log"
  node_command "$1"
  "${cmd[@]}" --no-shell >"$log" 2>&1 </dev/null &
  node_pids+=($!)
}
for k in $(seq 1 "$nodes"); do start_node "$k"; done
# Up: each node's two lines, after its start level 1 (the core) and after level 2 (the edge, its REST API and the
# dashboard); either says WITH PROBLEMS when something there did not start, such as the HTTP server on a port taken
# after the check above. Such a node is not reported ready: the script shows why and stops them all.
for k in $(seq 1 "$nodes"); do
  await_line "${node_pids[k - 1]}" "$state_dir/$(node_name "$k")/node.log" 'fabric node \(ready\|started\) in' \
    "$(node_name "$k")"
done
for k in $(seq 1 "$nodes"); do
  name="$(node_name "$k")"; log="$state_dir/$name/node.log"
  await_line "${node_pids[k - 1]}" "$log" 'fabric node: \(start levels\|started in\)' "$name"
  problems="$(grep -E '^fabric node:? started in [0-9]+ ms WITH PROBLEMS: ' "$log" | sed 's/^.* WITH PROBLEMS: //')" \
    || true
  [[ -n $problems ]] || continue
  taken="$(sed -n 's/.*HTTP server (REST API, dashboard) is not listening: port \([0-9]*\) .*/\1/p' <<<"$problems")"
  if [[ -n $taken ]]; then
    echo "fabric-nodes: $name started without its REST API and dashboard: port $taken of its HTTP server was" \
      "taken when it started (by a program that took it after this script found it free); $(http_port_hint)" \
      "(log: $log)" >&2
  else
    echo "fabric-nodes: $name started WITH PROBLEMS (log: $log):" >&2
    sed 's/^/  /' <<<"$problems" >&2
  fi
  exit 1
done

# joined: each node's log says it joined, or why it did not: at once when it does not join at all (its key), after
# reach_grace_s when it cannot reach the broker (a first attempt may fail while the broker warms up; the node retries)
for k in $(seq 1 "$nodes"); do
  log="$state_dir/$(node_name "$k")/node.log"
  deadline=$((SECONDS + join_timeout_s)) grace=$((SECONDS + reach_grace_s))
  until grep -q "Fabric .*: node .* joined through " "$log" 2>/dev/null; do
    signs='does not join a fabric'
    (( SECONDS >= grace )) && signs+='|cannot reach the broker'
    trouble="$(grep -m1 -E "$signs" "$log" 2>/dev/null | sed 's/^.* - //')" || true
    if [[ -n $trouble ]] || (( SECONDS >= deadline )); then
      echo "fabric-nodes: $(node_name "$k") did not join the fabric '$fabric_name' through $broker_uri:" \
        "${trouble:-no word of it within $join_timeout_s s} (log: $log)" >&2
      exit 1
    fi
    sleep 0.1
  done
done

echo "fabric-nodes: fabric '$fabric_name' of $nodes node(s) through $broker_uri, ready:" >&2
for k in $(seq 1 "$nodes"); do
  name="$(node_name "$k")"
  echo "  $name  REST http://127.0.0.1:$((http_base + k - 1))/sensinact  state $state_dir/$name" \
    " log $state_dir/$name/node.log  pid ${node_pids[k - 1]}" >&2
done
echo "fabric-nodes: Ctrl-C (or kill $$) stops every node$( [[ -n $broker_pid ]] && echo " and the broker")" >&2

# Runs until a signal (the traps exit, the EXIT trap stops everything) or until a node or the embedded broker ends,
# which the script then names, with its exit code.
set +e
watched=("${node_pids[@]}")
[[ -n $broker_pid ]] && watched+=("$broker_pid")
wait -n "${watched[@]}"
status=$?
ended="a process of the fabric"
for k in $(seq 1 "$nodes"); do # the one that ended was reaped by 'wait -n': no process has its pid now
  kill -0 "${node_pids[k - 1]}" 2>/dev/null || { ended="$(node_name "$k") (pid ${node_pids[k - 1]})"; break; }
done
if [[ -n $broker_pid ]] && ! kill -0 "$broker_pid" 2>/dev/null; then
  ended="the embedded broker (pid $broker_pid, log $broker_log)"
fi
how="exit code $status"
(( status > 128 && status < 160 )) && how+=", signal $(kill -l $((status - 128)))"
echo "fabric-nodes: $ended ended ($how); stopping the others" >&2
exit 1
