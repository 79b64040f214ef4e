#include "ui/machine/machine_choice.h"

#include "ui/machine/machine_ui_registry.h"

#include <QInputDialog>
#include <QStringList>

namespace CutCell::ui {

std::string askMachine(QWidget* parent, const std::string& current) {
    QStringList titles;
    int preselect = 0;
    for (const MachineUi* m : machineUis()) {
        if (m->id() == current) preselect = static_cast<int>(titles.size());
        titles << m->title();
    }
    bool ok = false;
    const QString chosen = QInputDialog::getItem(
        parent, QObject::tr("New job"), QObject::tr("Machine for the new job:"), titles, preselect,
        /*editable=*/false, &ok);
    if (!ok) return {};
    const auto i = titles.indexOf(chosen);
    return i < 0 ? std::string() : machineUis()[static_cast<size_t>(i)]->id();
}

} // namespace CutCell::ui
