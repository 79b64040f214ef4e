#pragma once
// A parameter page made to fit a narrow pane (1280x720: the form column is about 424 px wide):
// long form labels wrap onto two lines, choice boxes ask for the width of a short entry (a long
// entry is elided, the whole one shows in the open list), number fields take 70 px at least
// (not the width of their range's widest number), a long group box title or button text
// keeps the words before its parenthesis (the parenthesis goes into a note at the top of the
// box, or into the button's tooltip).
// Without it a German label or a long choice made the page wider than its pane: the pane
// scrolled sideways and cut the units and the right-aligned values at its edge (issue 21,
// defect 12).
//
// Threading contract: GUI thread only.
class QWidget;

namespace CutCell::ui {

// Applies the above to every form layout, choice box and check box inside `page`.
void narrowPage(QWidget* page);

} // namespace CutCell::ui
