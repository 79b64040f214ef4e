#!/usr/bin/env bash
# Installs the independent Sparkplug B host's npm packages (tests/peer/sparkplug: npm `mqtt` and
# `sparkplug-payload`, pinned by package-lock.json) when they are missing. Exit 77 (ctest:
# skipped) when Node.js/npm are not installed or the npm registry cannot be reached: the tests
# that need the independent decoder then report skipped, never passed.
set -uo pipefail
dir="${1:-$(dirname "$0")/../tests/peer/sparkplug}"
loads() { (cd "$dir" && node -e "require('mqtt'); require('sparkplug-payload')") >/dev/null 2>&1; }
[ -f "$dir/node_modules/sparkplug-payload/package.json" ] && loads && exit 0
if ! command -v npm >/dev/null || ! command -v node >/dev/null; then
  echo "sparkplug_peer_deps: node/npm not installed (apt-get install nodejs npm)" >&2
  exit 77
fi
# No native add-ons here; install scripts are not needed.
if ! (cd "$dir" && npm ci --no-audit --no-fund --ignore-scripts); then
  echo "sparkplug_peer_deps: npm ci failed in $dir (is the npm registry reachable?)" >&2
  exit 77
fi
if ! loads; then
  echo "sparkplug_peer_deps: mqtt or sparkplug-payload does not load in $dir" >&2
  rm -rf "$dir/node_modules"
  exit 77
fi
