#include "ui/forms/number_fields.h"

#include <QFocusEvent>
#include <QLocale>
#include <QStyle>
#include <QTimer>
#include <QToolTip>
#include <QWheelEvent>

#include <charconv>
#include <cmath>
#include <limits>
#include <string>

namespace CutCell::ui {
namespace {

constexpr int kRefusalShownMs = 1500;

TypedNumber refused(QString why, TypedNumber::Kind kind = TypedNumber::Kind::Refused) {
    TypedNumber r;
    r.kind = kind;
    r.why = std::move(why);
    return r;
}

bool isDigit(QChar c) {
    return c >= QLatin1Char('0') && c <= QLatin1Char('9');
}

// The text between the field's prefix and suffix, as the operator typed it.
QString typedPart(const QString& input, const QString& prefix, const QString& suffix) {
    QString s = input;
    if (!prefix.isEmpty() && s.startsWith(prefix)) s.remove(0, prefix.size());
    if (!suffix.isEmpty() && s.endsWith(suffix)) s.chop(suffix.size());
    return s.trimmed();
}

// A limit as the field shows it (its locale, its decimals, its unit).
QString shownLimit(const QLocale& locale, double v, int decimals, const QString& suffix) {
    QLocale l = locale;
    l.setNumberOptions(l.numberOptions() | QLocale::OmitGroupSeparator);
    return l.toString(v, 'f', decimals) + suffix;
}

// Whether more typing can still bring `v` into [min, max]: digits added to a number only make
// it larger in magnitude, so a value beyond the limit on its own side of zero is final.
bool beyondRepair(double v, double min, double max) {
    return (v >= 0 && v > max) || (v < 0 && v < min);
}

QString rangeWhy(const QLocale& locale, double min, double max, int decimals,
                 const QString& suffix) {
    return DecimalField::tr("takes %1 to %2")
        .arg(shownLimit(locale, min, decimals, suffix), shownLimit(locale, max, decimals, suffix));
}

QString sentence(const QString& typed, const QString& name, const QString& why) {
    return DecimalField::tr("'%1' refused: %2 %3").arg(typed, name, why);
}

// The shared validate() of both fields: Acceptable in range, Intermediate while the number
// is incomplete or below a limit that more digits may reach, Invalid (and said) otherwise.
QValidator::State validateTyped(const QString& typed, int decimals, double min, double max,
                                const QLocale& locale, const QString& suffix, const QString& name,
                                InputRefusal* refusal) {
    const TypedNumber n = readTypedNumber(typed, decimals, min < 0);
    switch (n.kind) {
    case TypedNumber::Kind::Partial:
        return QValidator::Intermediate;
    case TypedNumber::Kind::Refused:
        refusal->refuse(n.why.arg(name));
        return QValidator::Invalid;
    case TypedNumber::Kind::Held:
        refusal->refuse(n.why.arg(name));
        return QValidator::Intermediate;
    case TypedNumber::Kind::Number:
        break;
    }
    if (n.value >= min && n.value <= max) return QValidator::Acceptable;
    if (beyondRepair(n.value, min, max)) {
        refusal->refuse(sentence(typed, name, rangeWhy(locale, min, max, decimals, suffix)));
        return QValidator::Invalid;
    }
    return QValidator::Intermediate;
}

// fixup(): the field is left with text that is not a number in range (Enter, focus out). The
// operator is told why, and the caller puts back the value from before the edit. Returns
// whether the text was refused.
bool refuseLeftover(const QString& typed, int decimals, double min, double max,
                    const QLocale& locale, const QString& suffix, const QString& name,
                    InputRefusal* refusal) {
    const TypedNumber n = readTypedNumber(typed, decimals, min < 0);
    if (n.kind == TypedNumber::Kind::Number && n.value >= min && n.value <= max) return false;
    const QString kept = DecimalField::tr("; the previous value is kept");
    if (n.kind == TypedNumber::Kind::Held || n.kind == TypedNumber::Kind::Refused) {
        refusal->refuse(n.why.arg(name) + kept);
        return true;
    }
    const QString why = n.kind == TypedNumber::Kind::Number
                            ? rangeWhy(locale, min, max, decimals, suffix)
                            : DecimalField::tr("needs a number");
    refusal->refuse(sentence(typed, name, why) + kept);
    return true;
}

} // namespace

TypedNumber readTypedNumber(const QString& text, int decimals, bool negativeAllowed) {
    const QString s = text.trimmed();
    // The phrases keep %1 for the field's name (validateTyped fills it in).
    const auto says = [](const QString& what, const QString& why,
                         TypedNumber::Kind kind = TypedNumber::Kind::Refused) {
        return refused(DecimalField::tr("'%1' refused: %2 %3").arg(what, QStringLiteral("%1"), why),
                       kind);
    };
    constexpr auto held = TypedNumber::Kind::Held;
    int i = 0;
    if (!s.isEmpty() && (s[0] == QLatin1Char('+') || s[0] == QLatin1Char('-'))) {
        if (s[0] == QLatin1Char('-') && !negativeAllowed)
            return says(QStringLiteral("-"), DecimalField::tr("takes no negative numbers"));
        i = 1;
    }
    int separators = 0;
    int before = 0;
    int after = 0;
    for (; i < s.size(); ++i) {
        const QChar c = s[i];
        if (isDigit(c)) {
            ++(separators ? after : before);
        } else if (c == QLatin1Char('.') || c == QLatin1Char(',')) {
            if (decimals == 0) return says(s, DecimalField::tr("takes a whole number"), held);
            if (++separators > 1)
                return says(s,
                            DecimalField::tr("takes one decimal separator ('.' or ','), "
                                             "no group separators"),
                            held);
        } else if (c == QLatin1Char('+') || c == QLatin1Char('-')) {
            return says(QString(c), DecimalField::tr("takes a sign only in front"));
        } else {
            return says(QString(c), DecimalField::tr("takes a number (digits, a sign, '.' or ',' "
                                                     "as the decimal point)"));
        }
    }
    if (before + after == 0) return {}; // "", "-", "," ...: not yet a number
    if (after > decimals)
        return says(s, DecimalField::tr("keeps %n decimal(s)", nullptr, decimals), held);
    std::string ascii = s.toStdString();
    for (char& c : ascii)
        if (c == ',') c = '.';
    if (!ascii.empty() && ascii.front() == '+') ascii.erase(0, 1);
    if (!ascii.empty() && ascii.back() == '.') ascii.pop_back(); // "2." reads as 2
    double v = 0.0;
    // from_chars: the C notation whatever the process's LC_NUMERIC (strtod would follow it).
    const auto [end, ec] = std::from_chars(ascii.data(), ascii.data() + ascii.size(), v);
    if (ec != std::errc() || end != ascii.data() + ascii.size() || !std::isfinite(v))
        return says(s, DecimalField::tr("takes a finite number"));
    TypedNumber r;
    r.kind = TypedNumber::Kind::Number;
    r.value = v;
    return r;
}

InputRefusal::InputRefusal(QWidget* field)
    : QObject(field), field_(field), flash_(new QTimer(this)) {
    flash_->setSingleShot(true);
    flash_->setInterval(kRefusalShownMs);
    connect(flash_, &QTimer::timeout, this, [this] { mark(false); });
}

void InputRefusal::refuse(const QString& why) {
    field_->setProperty("refusedInput", why);
    mark(true);
    if (field_->isVisible())
        QToolTip::showText(field_->mapToGlobal(QPoint(0, field_->height())), why, field_);
    flash_->start();
}

void InputRefusal::mark(bool on) {
    if (field_->property("refused").toBool() == on) return;
    field_->setProperty("refused", on);
    field_->style()->unpolish(field_);
    field_->style()->polish(field_);
}

// ---- DecimalField ------------------------------------------------------------------------

DecimalField::DecimalField(QWidget* parent)
    : QDoubleSpinBox(parent), refusal_(new InputRefusal(this)) {
    // Not WheelFocus (the spin boxes' default): a wheel turned over the form scrolls it.
    setFocusPolicy(Qt::StrongFocus);
    connect(this, &QAbstractSpinBox::editingFinished, this, [this] { editStart_ = value(); });
}

void DecimalField::focusInEvent(QFocusEvent* event) {
    editStart_ = value();
    QDoubleSpinBox::focusInEvent(event);
}

QValidator::State DecimalField::validate(QString& input, int& pos) const {
    (void)pos;
    return validateTyped(typedPart(input, prefix(), suffix()), decimals(), minimum(), maximum(),
                         locale(), suffix(), name_.isEmpty() ? objectName() : name_, refusal_);
}

double DecimalField::valueFromText(const QString& text) const {
    const TypedNumber n = readTypedNumber(typedPart(text, prefix(), suffix()), decimals(), true);
    return n.kind == TypedNumber::Kind::Number ? n.value : value();
}

QString DecimalField::textFromValue(double v) const {
    QLocale l = locale();
    l.setNumberOptions(l.numberOptions() | QLocale::OmitGroupSeparator);
    // Rounded to the shown decimals, a tiny negative value is 0, not "-0.000".
    if (std::abs(v) < 0.5 * std::pow(10.0, -decimals())) v = 0.0;
    return l.toString(v, 'f', decimals());
}

void DecimalField::fixup(QString& input) const {
    // Nothing is repaired (Qt's own fixup drops the locale's group separators: "2.5" -> "25"
    // under de_DE); a leftover that is not a number in range is refused and said.
    if (refuseLeftover(typedPart(input, prefix(), suffix()), decimals(), minimum(), maximum(),
                       locale(), suffix(), name_.isEmpty() ? objectName() : name_, refusal_))
        input = prefix() + textFromValue(editStart_) + suffix(); // Qt takes it as the value
}

void DecimalField::wheelEvent(QWheelEvent* event) {
    if (!hasFocus()) {
        event->ignore(); // to the scroll area around the form
        return;
    }
    QDoubleSpinBox::wheelEvent(event);
}

// ---- WholeNumberField --------------------------------------------------------------------

WholeNumberField::WholeNumberField(QWidget* parent)
    : QSpinBox(parent), refusal_(new InputRefusal(this)) {
    setFocusPolicy(Qt::StrongFocus);
    connect(this, &QAbstractSpinBox::editingFinished, this, [this] { editStart_ = value(); });
}

void WholeNumberField::focusInEvent(QFocusEvent* event) {
    editStart_ = value();
    QSpinBox::focusInEvent(event);
}

QValidator::State WholeNumberField::validate(QString& input, int& pos) const {
    (void)pos;
    return validateTyped(typedPart(input, prefix(), suffix()), 0, minimum(), maximum(), locale(),
                         suffix(), name_.isEmpty() ? objectName() : name_, refusal_);
}

int WholeNumberField::valueFromText(const QString& text) const {
    const TypedNumber n = readTypedNumber(typedPart(text, prefix(), suffix()), 0, true);
    if (n.kind != TypedNumber::Kind::Number) return value();
    const double lo = std::numeric_limits<int>::min();
    const double hi = std::numeric_limits<int>::max();
    return static_cast<int>(std::llround(std::min(std::max(n.value, lo), hi)));
}

QString WholeNumberField::textFromValue(int v) const {
    QLocale l = locale();
    l.setNumberOptions(l.numberOptions() | QLocale::OmitGroupSeparator);
    return l.toString(v);
}

void WholeNumberField::fixup(QString& input) const {
    if (refuseLeftover(typedPart(input, prefix(), suffix()), 0, minimum(), maximum(), locale(),
                       suffix(), name_.isEmpty() ? objectName() : name_, refusal_))
        input = prefix() + textFromValue(editStart_) + suffix();
}

void WholeNumberField::wheelEvent(QWheelEvent* event) {
    if (!hasFocus()) {
        event->ignore();
        return;
    }
    QSpinBox::wheelEvent(event);
}

} // namespace CutCell::ui
