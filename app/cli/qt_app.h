#pragma once
// The CLI's CAN commands need a QCoreApplication (Qt's plugin loader, event dispatchers of the
// device threads); the rest of cutcell-cli runs without one. Null when one exists already.
#include <QCoreApplication>

#include <memory>

namespace cutcell::cli {

inline std::unique_ptr<QCoreApplication> ensureQCoreApplication() {
    if (QCoreApplication::instance()) return nullptr;
    static int argc = 1;
    static char name[] = "cutcell-cli";
    static char* argv[] = {name, nullptr};
    return std::make_unique<QCoreApplication>(argc, argv);
}

} // namespace cutcell::cli
