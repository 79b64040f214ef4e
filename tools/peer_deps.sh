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
# Install scripts stay on: node-crc (a dependency of canopen) builds its native add-on there.
if ! (cd "$dir" && npm ci --no-audit --no-fund); then
  echo "peer_deps: npm ci failed in $dir (is the npm registry reachable?)" >&2
  exit 77
fi
if ! (cd "$dir" && node -e "require('canopen')") >/dev/null; then
  echo "peer_deps: the canopen package does not load in $dir (its native add-on node-crc did not build)" >&2
  rm -rf "$dir/node_modules"
  exit 77
fi
