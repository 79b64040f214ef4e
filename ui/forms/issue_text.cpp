#include "ui/forms/issue_text.h"
#include "ui/panels/engine_text.h"
#include "ui/shown_number.h"

#include <QCoreApplication>

#include <cmath>

namespace CutCell::ui {

QString issueText(const cutcell::JobIssue& issue, const QString& label) {
    const QString key = QString::fromStdString(issue.key);
    const QString name = label.isEmpty() ? key : label;
    if (std::isfinite(issue.lo) && std::isfinite(issue.hi)) {
        const QString unit = QString::fromStdString(issue.unit);
        if (!std::isfinite(issue.value))
            return QCoreApplication::translate(
                       "IssueText", "%1 is not a finite number: it must lie in [%2, %3] %4")
                .arg(name, shownSignificant(issue.lo, 6), shownSignificant(issue.hi, 6), unit);
        return QCoreApplication::translate("IssueText", "%1 = %2 %3 is outside [%4, %5] %3")
            .arg(name, shownSignificant(issue.value, 6), unit, shownSignificant(issue.lo, 6),
                 shownSignificant(issue.hi, 6));
    }
    // In the GUI's language (ui/panels/engine_text.h: core's sentences are messageC templates).
    // The job names a machine's keys under "machine." (schema 2); the templates name them as
    // the machine's section does.
    QString message = QString::fromStdString(issue.message);
    const QString machinePrefix = QStringLiteral("machine.");
    if (message.startsWith(machinePrefix))
        message = machinePrefix + engineText(message.mid(machinePrefix.size()));
    else
        message = engineText(message);
    // The key as the job file spells it (schema 2 puts the machine's keys under "machine.").
    if (!label.isEmpty() && !key.isEmpty()) {
        message.replace(QStringLiteral("machine.") + key, label);
        message.replace(key, label);
    }
    return message;
}

} // namespace CutCell::ui
