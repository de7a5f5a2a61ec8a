#!/bin/sh
# Answers the paper's φ1-φ5 (section 6.3) on the warehouse's closed system (src/main/bip/WarehouseEnvironment.bip)
# with the bip CLI and writes the tables, CSV and plots (like the paper's Figs. 14 and 15) to figures/.
# Usage, from the repository root: behaviours/system-tests/paper-figures.sh [--threads N] [--seed S] ...
# (extra arguments go to every `bip smc` run). Builds what it needs first (offline; drop -o on a fresh clone).
set -eu
cd "$(dirname "$0")/../.."
mvn -B -q -o -pl behaviours/system-tests -am verify -DskipTests -Dbip.smc.skip=true
B=behaviours
OUT=$B/system-tests/figures
mkdir -p "$OUT"
bip() {
    java -jar bip/bip-cli/target/bip.jar smc $B/system-tests/src/main/bip/WarehouseEnvironment.bip \
        -I $B/events/src/main/bip -I $B/robot/src/main/bip -I $B/door/src/main/bip -I $B/orchestrator/src/main/bip \
        --cp $B/system-tests/target/test-classes:$B/orchestrator/target/classes "$@"
}
P=$B/system-tests/src/main/bip/paper
bip --properties $P/fig14.smc --csv "$OUT/fig14.csv" --svg "$OUT/fig14-phi2-phi4.svg" "$@" | tee "$OUT/fig14.txt"
bip --properties $P/fig15.smc --csv "$OUT/fig15.csv" --svg "$OUT/fig15-phi5.svg" "$@" | tee "$OUT/fig15.txt"
bip --properties $P/paper-literal.smc --csv "$OUT/literal.csv" "$@" | tee "$OUT/literal.txt"
