#pragma once
// The operator station's users and audit trail (devices/record/, the production record's file)
// wired into its windows: the log-in panel in the operator column, the forms' fields read-only
// above the logged-in level, Start behind a log-in, and each parameter change, E-STOP, reset,
// override change and recovery in the audit trail under the user's name.
#include <string>

namespace CutCell::ui {
class AccessControl;
class MainWindow;
} // namespace CutCell::ui

namespace cutcell::app {

// Opens users and trail in the record at `where` ("" = the data folder's, "off" = none: then
// single-user without a trail). Returns a line for the operator.
std::string openStationAccess(const std::string& where);
CutCell::ui::AccessControl* stationAccess();
// Wires a (new or rebuilt) window to the station's access.
void attachStationAccess(CutCell::ui::MainWindow& window);
// Closes users and trail (before the application object goes).
void closeStationAccess();

} // namespace cutcell::app
