#include "ui/forms/narrow_page.h"

#include <QAbstractSpinBox>
#include <QBoxLayout>
#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QWidget>

#include <algorithm>

namespace CutCell::ui {
namespace {

// Wider than this, a title or a button text is split at its parenthesis: the pane at
// 1280x720 leaves a group box about 380 px inside its margins.
constexpr int kLongTextPx = 260;
// A form label wider than this wraps onto a second line.
constexpr int kLongLabelPx = 150;

// "Path arm (3R in the cut plane, ...)" -> {"Path arm", "3R in the cut plane, ..."}; a text
// without a final parenthesis stays whole.
bool splitAtParenthesis(const QString& text, QString* head, QString* detail) {
    const qsizetype open = text.indexOf(QStringLiteral(" ("));
    if (open <= 0 || !text.endsWith(QLatin1Char(')'))) return false;
    *head = text.left(open);
    *detail = text.mid(open + 2, text.size() - open - 3);
    return true;
}

void narrowGroupTitle(QGroupBox* box) {
    QString head, detail;
    if (box->property("cutcellNarrowed").toBool() ||
        box->fontMetrics().horizontalAdvance(box->title()) <= kLongTextPx ||
        !splitAtParenthesis(box->title(), &head, &detail))
        return;
    auto* note = new QLabel(detail, box);
    note->setObjectName("groupDetail");
    note->setWordWrap(true);
    if (auto* form = qobject_cast<QFormLayout*>(box->layout()))
        form->insertRow(0, note);
    else if (auto* column = qobject_cast<QBoxLayout*>(box->layout()))
        column->insertWidget(0, note);
    else {
        delete note; // a grid: no row to put it in, the title stays whole
        return;
    }
    box->setTitle(head);
    box->setProperty("cutcellNarrowed", true);
}

void narrowButton(QPushButton* button) {
    QString head, detail;
    if (button->fontMetrics().horizontalAdvance(button->text()) <= kLongTextPx ||
        !splitAtParenthesis(button->text(), &head, &detail))
        return;
    button->setToolTip(button->toolTip().isEmpty()
                           ? button->text()
                           : button->text() + QStringLiteral("\n") + button->toolTip());
    button->setText(head);
}

} // namespace

void narrowPage(QWidget* page) {
    for (QFormLayout* form : page->findChildren<QFormLayout*>()) {
        for (int row = 0; row < form->rowCount(); ++row) {
            QLayoutItem* item = form->itemAt(row, QFormLayout::LabelRole);
            // Only a long label: wrapping all of them narrowed the label column until a
            // label took three lines, and a form row does not grow past two.
            auto* label = item ? qobject_cast<QLabel*>(item->widget()) : nullptr;
            const int textPx = label ? label->fontMetrics().horizontalAdvance(label->text()) : 0;
            if (textPx <= kLongLabelPx) continue;
            label->setWordWrap(true);
            // Half its text wide at least (plus a word's slack): two lines, never three.
            label->setMinimumWidth(std::min(textPx, textPx / 2 + 24));
        }
    }
    // A number field's range (often +-1e9) makes it ask for ~143 px: 70 hold any value shown.
    for (QAbstractSpinBox* field : page->findChildren<QAbstractSpinBox*>())
        if (field->minimumWidth() == 0) field->setMinimumWidth(70);
    for (QComboBox* box : page->findChildren<QComboBox*>()) {
        box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        box->setMinimumContentsLength(12);
    }
    for (QGroupBox* box : page->findChildren<QGroupBox*>())
        narrowGroupTitle(box);
    for (QPushButton* button : page->findChildren<QPushButton*>())
        narrowButton(button);
}

} // namespace CutCell::ui
