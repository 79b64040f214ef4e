#pragma once
// The CLI's CAN commands need a QCoreApplication (Qt's plugin loader, event dispatchers of the
// device threads); the rest of cutcell-cli runs without one. Null when one exists already.
#include <QCoreApplication>
#include <QLoggingCategory>

#include <clocale>
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
    auto app = std::make_unique<QCoreApplication>(argc, argv);
    // QCoreApplication sets LC_ALL from the environment; the CLI's messages keep the decimal
    // point (the files go through core/common/c_format.h anyway).
    std::setlocale(LC_NUMERIC, "C");
    return app;
}

} // namespace cutcell::cli
