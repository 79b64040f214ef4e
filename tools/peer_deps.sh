#!/usr/bin/env bash
# Installs the independent CANopen peer's npm packages (tests/peer: the npm package `canopen`,
# pinned by package-lock.json) when they are missing. Exit 77 (ctest: skipped) when Node.js/npm
# are not installed or the npm registry cannot be reached: the peer test then reports skipped.
set -uo pipefail
dir="${1:-$(dirname "$0")/../tests/peer}"
[ -f "$dir/node_modules/canopen/package.json" ] && exit 0
if ! command -v npm >/dev/null || ! command -v node >/dev/null; then
  echo "peer_deps: node/npm not installed (tools/setup.sh installs nodejs npm)" >&2
  exit 77
fi
if ! (cd "$dir" && npm ci --no-audit --no-fund --ignore-scripts); then
  echo "peer_deps: npm ci failed in $dir (is the npm registry reachable?)" >&2
  exit 77
fi
