#include "ui/forms/issue_text.h"

#include <QCoreApplication>
#include <QLocale>

#include <cmath>

namespace CutCell::ui {
namespace {

QString number(double v) {
    QLocale l;
    l.setNumberOptions(l.numberOptions() | QLocale::OmitGroupSeparator);
    return l.toString(v, 'g', 6);
}

} // namespace

QString issueText(const cutcell::JobIssue& issue, const QString& label) {
    const QString key = QString::fromStdString(issue.key);
    const QString name = label.isEmpty() ? key : label;
    if (std::isfinite(issue.lo) && std::isfinite(issue.hi)) {
        const QString unit = QString::fromStdString(issue.unit);
        if (!std::isfinite(issue.value))
            return QCoreApplication::translate(
                       "IssueText", "%1 is not a finite number: it must lie in [%2, %3] %4")
                .arg(name, number(issue.lo), number(issue.hi), unit);
        return QCoreApplication::translate("IssueText", "%1 = %2 %3 is outside [%4, %5] %3")
            .arg(name, number(issue.value), unit, number(issue.lo), number(issue.hi));
    }
    QString message = QString::fromStdString(issue.message);
    // The key as the job file spells it (schema 2 puts the machine's keys under "machine.").
    if (!label.isEmpty() && !key.isEmpty()) {
        message.replace(QStringLiteral("machine.") + key, label);
        message.replace(key, label);
    }
    return message;
}

} // namespace CutCell::ui
