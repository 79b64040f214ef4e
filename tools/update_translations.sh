#!/usr/bin/env bash
# Brings resources/i18n/cutcell_de.ts up to date with the tr() texts of ui/, app/ and plots/ and
# the form labels of core's field tables (tools/core_labels.py) and the engine's event texts
# (tools/core_messages.py)
# (new texts come in unfinished, texts no longer in the code are dropped). Translate the new
# ones with Qt Linguist (`linguist resources/i18n/cutcell_de.ts`, package linguist-qt6) or by
# hand; the build compiles the catalogue. tests: gui.translations_complete fails while any text
# is unfinished or the catalogue lags the code.
set -euo pipefail
cd "$(dirname "$0")/.."
lupdate=${LUPDATE:-/usr/lib/qt6/bin/lupdate}
# core's form labels (plain C++ there) as QT_TRANSLATE_NOOP lines for lupdate.
/usr/bin/python3 tools/core_labels.py . > resources/i18n/core_labels.cpp
# core's event templates, compiled into the GUI (ui/panels/engine_text.cpp) and read by lupdate.
/usr/bin/python3 tools/core_messages.py . > resources/i18n/core_messages.cpp
exec "$lupdate" -no-obsolete -locations relative -I . ui app plots resources/i18n/core_labels.cpp \
    resources/i18n/core_messages.cpp \
    -target-language de_DE -ts resources/i18n/cutcell_de.ts "$@"
