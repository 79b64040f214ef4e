#pragma once
// The run model's words on screen (core/engine/run_terms.h): what the progress counts, what a
// run made, the process tool; translated, in the machine's own terms. A machine's module fills
// the terms; no panel knows which machine it is.
//
// Threading contract: GUI thread only (tr()).
#include "core/engine/engine_types.h"
#include "core/engine/run_terms.h"

#include <QString>

namespace CutCell::ui {

// "Point", "Piece", "Stroke": the caption of the progress figure.
QString countCaption(cutcell::WorkCount w);
// "point", "piece", "stroke" (n == 1) or their plurals.
QString countNoun(cutcell::WorkCount w, long n);
// "Parts" (whole runs of a path machine), "Pieces", "Strokes": the counter of what was made.
QString madeCaption(cutcell::WorkCount w);
// "pierce(s)", "piece(s)", "stroke(s)" for n made.
QString madeNoun(cutcell::WorkCount w, long n);
// The tool's name as the terms give it, translated where known ("torch", "saw", "cutter").
QString toolWord(const cutcell::RunTerms& terms);
// The engine state as an operator reads it: "Emergency stop", "Feed hold" (not the enum's
// "EmergencyStop", "Paused"), translated.
QString stateWord(cutcell::EngineState s);
// Where a run stopped, in the machine's terms: "point 12 / 40, 210.3 of 530.1 mm" for a path,
// "piece 8 of 10, 7 pieces made" for the saw, "stroke 2 of 3, 1 stroke made" for the crank.
QString stopFigures(const cutcell::RunTerms& terms, const cutcell::RunStopPoint& at,
                    double pathLengthMm);

} // namespace CutCell::ui
