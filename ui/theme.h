#pragma once
// The dark industrial theme (resources/style/dark_industrial.qss, compiled into the ui
// library) and the Fusion style it is written for.
class QApplication;
class QString;

namespace CutCell::ui {

// Returns false (and leaves the default look) if the stylesheet resource is missing.
bool applyDarkIndustrialTheme(QApplication& app);
QString darkIndustrialStyleSheet();

} // namespace CutCell::ui
