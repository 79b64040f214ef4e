#pragma once
// Help -> About and Help -> Manual. The manual is the README's operator sections, compiled
// into the binary (resources/ui_resources.qrc), so it is there offline and matches the build.
//
// Threading contract: GUI thread only.
#include <QString>

class QDialog;
class QWidget;

namespace CutCell::ui {

// Version, build (commit, type, compiler), Qt and the machines this build knows, as rich text.
QString aboutText();
// The operator's sections of a README in Markdown: the "## The operator station" section and
// each machine's "### In the GUI" (under its machine's heading). Empty when it has none.
QString operatorManual(const QString& readmeMarkdown);
// The operator sections of the README compiled into this build; in German their translation
// (docs/manual_de.md).
QString builtInManual();
// The resource folder the manual's images are found in (its "docs/x.png" links).
QString manualImageRoot();
// A non-modal, resizable window showing builtInManual(); deleted when closed.
QDialog* makeManualWindow(QWidget* parent);

} // namespace CutCell::ui
