#pragma once
// The operator station's number fields. Qt's spin boxes read a typed number through the
// widget's QLocale, which takes the locale's group separator: in the C locale "2,5" became 25,
// under de_DE "2.5" became 25, silently. Here:
//   - '.' and ',' both read as the decimal point, whatever the locale (an operator on a German
//     desktop types either); a group separator is never read;
//   - anything else is refused visibly: a letter or a misplaced sign is dropped; a second
//     separator ("1.234,5" is ambiguous), a separator in a whole number or more decimals than
//     the field keeps stay on screen, marked, and are never taken: Enter puts back the value
//     the field had before this edit (typed key by key, "1.234,5" passes through 1.2, which
//     the field takes while it is typed; Enter restores the 400.0 it had); a number beyond
//     the field's range is refused likewise (never clamped or cut silently);
//   - values are shown in the field's locale (decimal comma on a German desktop), without
//     group separators, and never as "-0.000";
//   - the mouse wheel changes a value only in the field that has the focus: scrolling a form
//     scrolls it and leaves the values alone.
// A refusal sets the properties "refused" (true for 1.5 s, the stylesheet's red frame) and
// "refusedInput" (the sentence), and shows the sentence as a tooltip at the field.
//
// Threading contract: GUI thread only.
#include <QDoubleSpinBox>
#include <QSpinBox>
#include <QString>

class QTimer;

namespace CutCell::ui {

// How a typed text reads as a number.
struct TypedNumber {
    enum class Kind {
        Partial, // nothing yet, a lone sign or separator: may still become a number
        Number,  // `value` holds it
        Refused, // a key that is no part of a number (a letter): dropped, `why` says so
        Held,    // a number made ambiguous (a second separator, a separator in a whole number,
                 // more decimals than kept): kept on screen, marked and said, never taken;
                 // Enter puts the last value back. Dropping the key instead would join the
                 // digits around it: "2,5" in a whole-number field became 25.
    };
    Kind kind = Kind::Partial;
    double value = 0.0;
    QString why;
};

// Reads `text` (prefix and suffix already removed) as a number with at most `decimals` digits
// after the point (0: a whole number). Both '.' and ',' are the decimal point.
TypedNumber readTypedNumber(const QString& text, int decimals, bool negativeAllowed);

// Shows a refused input on a field: red frame for a moment, a tooltip, the two properties.
class InputRefusal : public QObject {
  public:
    explicit InputRefusal(QWidget* field);
    void refuse(const QString& why);

  private:
    void mark(bool on);
    QWidget* field_;
    QTimer* flash_;
};

// A field for a decimal number (QDoubleSpinBox with the reading above).
class DecimalField : public QDoubleSpinBox {
    Q_OBJECT
  public:
    explicit DecimalField(QWidget* parent = nullptr);
    // The name the refusal messages give the field (its label or its job key).
    void setFieldName(const QString& name) { name_ = name; }
    QString fieldName() const { return name_; }

    QValidator::State validate(QString& input, int& pos) const override;
    double valueFromText(const QString& text) const override;
    QString textFromValue(double value) const override;
    void fixup(QString& input) const override;

  protected:
    void wheelEvent(QWheelEvent* event) override;
    void focusInEvent(QFocusEvent* event) override;

  private:
    QString name_;
    InputRefusal* refusal_;
    double editStart_ = 0; // the value before this edit (focus in, or the last Enter)
};

// A field for a whole number (QSpinBox with the reading above: a separator is refused).
class WholeNumberField : public QSpinBox {
    Q_OBJECT
  public:
    explicit WholeNumberField(QWidget* parent = nullptr);
    void setFieldName(const QString& name) { name_ = name; }
    QString fieldName() const { return name_; }

    QValidator::State validate(QString& input, int& pos) const override;
    int valueFromText(const QString& text) const override;
    QString textFromValue(int value) const override;
    void fixup(QString& input) const override;

  protected:
    void wheelEvent(QWheelEvent* event) override;
    void focusInEvent(QFocusEvent* event) override;

  private:
    QString name_;
    InputRefusal* refusal_;
    int editStart_ = 0;
};

} // namespace CutCell::ui
