#!/usr/bin/env bash
# The README's screenshots of every machine (docs/i18n): each shipped job run once at 1280x720
# under Xvfb, in English and in German, pictured when the run ended.
#   tools/screenshots.sh [build-dir]
set -euo pipefail
cd "$(dirname "$0")/.."
gui="${1:-build}/app/gui/cutcell"
[ -x "$gui" ] || { echo "no $gui: build first (tools/setup.sh run)" >&2; exit 1; }
mkdir -p docs/i18n
for job in default_job profile_cutter_job section_steel_job flying_saw_job quick_return_job; do
  for language in en de; do
    out="docs/i18n/${job}_${language}.png"
    xvfb-run -a -s "-screen 0 1280x720x24" "$gui" --job "resources/jobs/$job.json" --run \
      --screenshot "$out" --size 1280x720 --language "$language" >/dev/null
    echo "$out"
  done
done
