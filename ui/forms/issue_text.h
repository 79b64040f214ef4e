#pragma once
// A job issue as the forms show it: the field's label (as the form names it) instead of the
// job file's key, and, for a value outside its range, the sentence in the GUI's language with
// the numbers in the locale's form ("Geschwindigkeit = 0 mm/s liegt außerhalb von 0,1 bis
// 500 mm/s"). Every other issue is core's sentence (a messageC template) translated as the
// engine's events are (ui/panels/engine_text.h), with the key replaced by the label.
//
// Threading contract: GUI thread only (QLocale default, translators).
#include "core/job/job_io.h"

#include <QString>

namespace CutCell::ui {

QString issueText(const cutcell::JobIssue& issue, const QString& label);

} // namespace CutCell::ui
