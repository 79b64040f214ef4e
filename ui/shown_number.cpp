#include "ui/shown_number.h"

#include <QLocale>

#include <cmath>

namespace CutCell::ui {
namespace {

QLocale shownLocale() {
    QLocale l;
    l.setNumberOptions(l.numberOptions() | QLocale::OmitGroupSeparator);
    return l;
}

} // namespace

QString shownNumber(double value, int decimals) {
    // Rounded to the shown decimals, a tiny negative value is 0.
    if (std::isfinite(value) && std::abs(value) < 0.5 * std::pow(10.0, -decimals)) value = 0.0;
    return shownLocale().toString(value, 'f', decimals);
}

QString shownSignificant(double value, int digits) {
    if (value == 0.0) value = 0.0; // -0 shows as 0
    return shownLocale().toString(value, 'g', digits);
}

} // namespace CutCell::ui
