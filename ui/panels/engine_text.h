#pragma once
// The motion engine's event texts in the GUI's language. core is pure C++ and writes its
// events in English from printf templates; tools/core_messages.py lists those templates and
// the words that go into them (resources/i18n/core_messages.cpp, "CoreMessage" context of the
// catalogue). engineText finds the template a text was formatted from, translates it and
// fills the values back in: numbers in the GUI language's form (1,250 s), the words inside
// (a state, the tool, a fault's reason) translated the same way. A text that no template
// matches (a device's own message, a job's name) is shown as it came. The log files keep the
// English text: they are written by core.
//
// Threading contract: GUI thread only (reads the installed translators and the default QLocale).
#include <QString>

namespace CutCell::ui {

QString engineText(const QString& english);

// For tests: the template `english` was formatted from (nullptr when none matches).
const char* engineTemplateOf(const QString& english);

} // namespace CutCell::ui
