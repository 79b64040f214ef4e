#include "ui/panels/elided_label.h"

#include <QResizeEvent>

#include <algorithm>

namespace CutCell::ui {
namespace {
// What the label asks for at most: a long text is elided, not a reason to grow.
constexpr int kMaxHintChars = 60;
} // namespace

ElidedLabel::ElidedLabel(const QString& text, QWidget* parent) : QLabel(parent) {
    setTextFormat(Qt::PlainText);
    setWordWrap(false);
    setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    setFullText(text);
}

void ElidedLabel::setFullText(const QString& text) {
    full_ = text;
    setToolTip(text);
    refit();
    updateGeometry();
}

QSize ElidedLabel::minimumSizeHint() const {
    const QFontMetrics fm = fontMetrics();
    return {fm.horizontalAdvance(QStringLiteral("M…")) + 2 * margin(),
            QLabel::minimumSizeHint().height()};
}

QSize ElidedLabel::sizeHint() const {
    const QFontMetrics fm = fontMetrics();
    const int full = fm.horizontalAdvance(full_) + 2 * margin();
    const int cap = fm.averageCharWidth() * kMaxHintChars;
    return {std::min(full, cap), QLabel::sizeHint().height()};
}

void ElidedLabel::resizeEvent(QResizeEvent* event) {
    QLabel::resizeEvent(event);
    refit();
}

void ElidedLabel::refit() {
    const int room = std::max(0, contentsRect().width() - 2 * margin());
    // The first line only: a message with line breaks is one line here, whole in the tooltip.
    QString line = full_;
    line.replace(QLatin1Char('\n'), QLatin1Char(' '));
    QLabel::setText(fontMetrics().elidedText(line, Qt::ElideRight, room));
}

} // namespace CutCell::ui
