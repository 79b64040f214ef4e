#pragma once
// The GUI's language: Qt Linguist catalogues (resources/i18n/cutcell_<code>.ts, compiled into
// the binary by qt_add_translations) plus Qt's own (dialog buttons, file dialog), and the
// number format that goes with it. Files stay in C notation whatever the language
// (core writes them); only what the operator reads follows it.
//
// The choice is remembered in QSettings ("ui/language"): "system" (the default) follows the
// desktop's locale — its translation when there is one, English otherwise, numbers in the
// desktop's own form — while an explicit language also brings its number format ("de":
// 2,5; "en": 2.5).
//
// Threading contract: GUI thread only.
#include <QList>
#include <QString>

namespace CutCell::ui {

struct GuiLanguage {
    QString code;       // "system", "en", "de"
    QString nativeName; // as the menu shows it: "English", "Deutsch"
};

// "system" first, then every language with a catalogue (English needs none).
QList<GuiLanguage> guiLanguages();
// The remembered choice ("system" when none or unknown).
QString rememberedLanguage();
void rememberLanguage(const QString& code);
// Installs the catalogues and the number locale for `code` ("system" resolves to the
// desktop's language). Replaces what an earlier call installed. False, with the reason, when
// the code is unknown; English then stays in place.
bool applyGuiLanguage(const QString& code, QString* why = nullptr);
// The language whose texts are shown now ("en" or "de"), after the last applyGuiLanguage.
QString shownLanguage();

} // namespace CutCell::ui
