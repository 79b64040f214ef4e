#pragma once
// A number as the operator station shows it: in the GUI language's form (ui/language.h sets the
// default QLocale: "2,5" in German, "2.5" in English), without group separators (a "1.234" in
// German must not read as 1.234 mm), and a value that rounds to zero never as "-0.000".
// QString::number and QString::arg(double) ignore the locale: text for the operator goes
// through here, files stay in C notation.
//
// Threading contract: GUI thread only (reads the default QLocale).
#include <QString>

namespace CutCell::ui {

// Fixed decimals ('f').
QString shownNumber(double value, int decimals);
// Significant digits ('g').
QString shownSignificant(double value, int digits);

} // namespace CutCell::ui
