#!/usr/bin/env bash
# CutCell set-up on Debian 12: installs what is missing (apt-get), configures, builds, then
#   tools/setup.sh run    starts the GUI on the simulated cell with the default job
#                         (no display: says so and runs a headless demo instead)
#   tools/setup.sh test   runs the whole test suite (also under ASan+UBSan, built with clang),
#                         then fuzzes the job parser for 60 s with the harness of that same
#                         build (tools/fuzz.sh: fails on a new finding)
# Works as root and through sudo. Re-running it is cheap: only missing packages are installed.
set -euo pipefail
cd "$(dirname "$0")/.."
mode="${1:-run}"
case "$mode" in run | test) ;; *) echo "usage: tools/setup.sh run|test" >&2; exit 64 ;; esac

packages=(
  build-essential cmake ninja-build pkg-config git
  libeigen3-dev libgtest-dev libgmock-dev
  libcli11-dev
  qt6-base-dev qt6-base-dev-tools libqt6opengl6-dev qt6-serialbus-dev libqt6serialbus6-bin
  qt6-tools-dev qt6-l10n-tools qt6-translations-l10n
  libqcustomplot-dev libvtk9-dev libgl1-mesa-dri
  xvfb xauth libsocketcan2
  openbox xdotool x11-apps netpbm dbus-daemon at-spi2-core python3-gi gir1.2-atspi-2.0
  poppler-utils linuxcnc-uspace
  clang-14 libfuzzer-14-dev libclang-rt-14-dev lld
  nodejs
  nlohmann-json3-dev locales
  libsqlite3-dev sqlite3 libsodium-dev libpq-dev postgresql
  liborocos-kdl-dev
  mosquitto libmosquitto-dev libprotobuf-dev protobuf-compiler openssl
)
# npm: Debian's package, unless an npm came with another nodejs build (e.g. NodeSource's).
command -v npm >/dev/null || packages+=(npm)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "== installing: ${missing[*]}"
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "need root or sudo to install: ${missing[*]}" >&2; exit 1; }
    sudo="sudo"
  fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# The locale tests run the writers under a decimal-comma locale (skipped without it).
if ! locale -a 2>/dev/null | grep -qi '^de_DE\.utf-\?8$'; then
  echo "== generating the de_DE.UTF-8 locale"
  ${sudo:-$([ "$(id -u)" -ne 0 ] && echo sudo)} localedef -i de_DE -f UTF-8 de_DE.UTF-8
fi

jobs=2
build=build
# Line tables only (-g1): backtraces, gdb's `bt` and sanitizer reports keep files and lines,
# and the cold build on two cores takes about a third less time than with full -g (measured on
# groove_arm.cpp: 9.3 s against 14.6 s; under ASan 23 s against 38 s). Both builds use it.
debug_flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG")
echo "== configuring and building ($build)"
cmake -S . -B "$build" -G Ninja "${debug_flags[@]}" >/dev/null
cmake --build "$build" -j "$jobs"

default_job=resources/jobs/default_job.json
if [ "$mode" = run ]; then
  if [ -x "$build/app/gui/cutcell" ] && { [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; }; then
    exec "$build/app/gui/cutcell" --job "$default_job"
  fi
  echo
  echo "No display here (DISPLAY and WAYLAND_DISPLAY are unset), so the GUI cannot open."
  echo "Running the headless demo instead: the default job simulated with both methods."
  echo
  "$build/app/cutcell-cli" validate "$default_job"
  mkdir -p runs/demo
  for method in static_pipe rotating_pipe; do
    echo
    "$build/app/cutcell-cli" simulate "$default_job" --method "$method" --report "runs/demo/report_$method.json"
  done
  exit 0
fi

# ctest, and when a test fails, a digest of its failure lines after the whole run: a CI log
# shown by head and tail loses the middle of a long test output, where a QtTest FAIL! line is.
run_ctest() {
  local dir="$1"
  shift
  ctest --test-dir "$dir" "$@" && return 0
  local status=$?
  local log="$dir/Testing/Temporary/LastTest.log"
  echo
  echo "== failure digest ($dir): the failed tests and their failure lines"
  cat "$dir/Testing/Temporary/LastTestsFailed.log" 2>/dev/null || true
  grep -a -n -E -A4 '^FAIL!  :|: Failure$|^\[  FAILED  \]|ERROR: AddressSanitizer|runtime error:|^QFATAL|^QWARN .*try [0-9]+:' \
    "$log" 2>/dev/null | cut -c1-400 | head -n 120 || true
  return "$status"
}

echo "== test suite"
# The independent CANopen peer's npm packages (pinned by tests/peer/package-lock.json).
tools/peer_deps.sh tests/peer || echo "(no npm packages: the CANopen peer test reports skipped)"
export QT_LOGGING_RULES="qt.canbus.plugins.virtualcan.info=false"
run_ctest "$build" --output-on-failure -j "$jobs" --timeout 600

echo "== test suite under AddressSanitizer + UndefinedBehaviorSanitizer"
san=build-asan
# One sanitised build for the tests and the fuzzer: clang with libFuzzer's coverage
# instrumentation (CUTCELL_FUZZ), so the harnesses need no build of their own (a separate
# fuzzing build of core took 147 s here; this build 429 s). -O1, the level the sanitizers'
# documentation names (about 40 % less compile time than -O2). A build-asan made by an
# earlier set-up with GCC is made again.
if [ -f "$san/CMakeCache.txt" ] && ! grep -q '^CMAKE_CXX_COMPILER:[A-Z]*=.*clang' "$san/CMakeCache.txt"; then
  rm -rf "$san"
fi
san_flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG")
CC=clang-14 CXX=clang++-14 cmake -S . -B "$san" -G Ninja "${san_flags[@]}" \
  -DCUTCELL_SANITIZE=ON -DCUTCELL_FUZZ=ON -DCUTCELL_BUILD_GUI=OFF >/dev/null
cmake --build "$san" -j "$jobs"
# Less the whole CAN runs (label realtime_run): their verdict is real-time tracking, which a
# sanitised build (2-3x slower) cannot keep on two cores. Less the four section-steel
# catalogue sweeps: the planner over every catalogue entry, 140 s of this stage's 305 s for
# the turnover sweep alone, and more than 13 min for the speed sweep (96 entries x 17 end cuts);
# less the torch IK's count against a 300-start multistart on 1000 poses (6.5 s normally, more
# than 5 min sanitised; the IK's round trip on 10 000 poses runs under the sanitisers);
# less the section-steel kerf's 295 random cuts (7 s normally, minutes sanitised; its other
# five tests run sanitised, the zero-kerf one over every point in 46 s);
# the other section-steel tests run that code under the sanitisers (the groove-pass speed
# test, the grooved and mitred plans). The normal build above ran them all.
ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1 \
  run_ctest "$san" --output-on-failure -j "$jobs" --timeout 900 -LE realtime_run \
  -E '^(EndCutPlan\.EveryCatalogueEntryPlans(AtTheEndsOfTheSpeedRange|ASquareAndAGroovedMitredEnd)|SectionTurnover\.EveryCatalogueEntryPlansItsSecondSetup|SectionEndCutSpeed\.EveryCatalogueEntryKeepsTheCuttingSpeedOnEveryMitre|SectionSteelGrooveArm\.TorchIkCountMatchesAMultistart|SectionSteelKerf\.EdgeRecoveredAndHalfKerfAcrossOnRandomCuts)$'

echo "== fuzzing the job parser (libFuzzer, 60 s)"
tools/fuzz.sh 60 "$san"
