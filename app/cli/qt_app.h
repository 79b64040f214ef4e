#pragma once
// The CLI's CAN commands need a QCoreApplication (Qt's plugin loader, event dispatchers of the
// device threads); the rest of cutcell-cli runs without one. Null when one exists already.
#include <QCoreApplication>
#include <QLoggingCategory>

#include <cstdlib>
#include <memory>

namespace cutcell::cli {

inline std::unique_ptr<QCoreApplication> ensureQCoreApplication() {
    if (QCoreApplication::instance()) return nullptr;
    // virtualcan narrates every connection at info level; keep the CLI's output readable
    // unless the user chose their own logging rules.
    if (!std::getenv("QT_LOGGING_RULES"))
        QLoggingCategory::setFilterRules(QStringLiteral("qt.canbus.plugins.virtualcan.info=false"));
    static int argc = 1;
    static char name[] = "cutcell-cli";
    static char* argv[] = {name, nullptr};
    return std::make_unique<QCoreApplication>(argc, argv);
}

} // namespace cutcell::cli
