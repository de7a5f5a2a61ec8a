#!/bin/sh
# Saves a screenshot of a running node's live dashboard once the page is live and has drawn its state, with headless
# Chromium and the browser tests' Selenium set-up (dashboard/browser-tests: Screenshot.java). For a person to look at
# what a run showed, e.g. from the warehouse scenario:
#   dashboard/screenshot.sh http://127.0.0.1:8181/dashboard/ target/scenario/dashboard-01.png
#   dashboard/screenshot.sh http://HOST:8181/dashboard/ out.png --token-file ~/.config/brain-iot/node/api-token
# Exit 0: written; 1: written, but the page was not live in time (see the message); 2: wrong arguments; 3: no
# Chromium (apt-get install -y chromium chromium-driver). Needs the browser tests compiled once:
#   mvn -B -pl dashboard/browser-tests -am package -DskipTests
set -eu
here=$(cd "$(dirname "$0")" && pwd)
tests="$here/browser-tests/target"
if [ ! -f "$tests/test-classpath.txt" ] || [ ! -d "$tests/test-classes/eu/brain/iot/dashboard/browser" ]; then
    echo "screenshot: $tests is not built; run: mvn -B -pl dashboard/browser-tests -am package -DskipTests" >&2
    exit 2
fi
exec "${JAVA_HOME:+$JAVA_HOME/bin/}java" -cp "$tests/test-classes:$(cat "$tests/test-classpath.txt")" \
    eu.brain.iot.dashboard.browser.Screenshot "$@"
