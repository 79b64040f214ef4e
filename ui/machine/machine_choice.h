#pragma once
// File -> New's question "which machine?": a modal list of the registered machines by title.
//
// Threading contract: GUI thread only.
#include <string>

class QWidget;

namespace CutCell::ui {

// The chosen machine's id; empty when the operator cancels.
std::string askMachine(QWidget* parent, const std::string& current);

} // namespace CutCell::ui
