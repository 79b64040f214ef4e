#pragma once
// How a machine speaks of a run: the run model every layer shares (the operator station's
// progress panel, recovery box and alarm list, the run log's summary, the engine's event texts).
// The machine's module fills it into its MotionProgram; nothing outside the module knows which
// machine it is. A torch machine counts path points and reports the length cut and its pierces;
// the flying saw counts pieces and reports their lengths; the quick-return cutter counts strokes.
#include <cstdint>
#include <string>
#include <vector>

namespace cutcell {

// What the run's progress counts (TelemetrySample / RunStopPoint point_index of point_count).
enum class WorkCount : std::uint8_t {
    PathPoints, // knots along one cut path of length_mm; made = pierces
    Pieces,     // pieces cut off a line; made = pieces finished
    Strokes,    // cutting strokes of a mechanism; made = strokes finished
};
const char* toString(WorkCount w);       // "path_points", "pieces", "strokes"
const char* unitSingular(WorkCount w);   // "point", "piece", "stroke"
const char* madeNounPlural(WorkCount w); // "pierces", "pieces", "strokes"

struct RunTerms {
    // The process tool as alarms and events name it: "torch", "saw", "cutter". The engine
    // says "<tool> off" and "<tool>: <fault>".
    std::string tool = "torch";
    // What "process OK" of that tool means: "arc established", "blade at speed".
    std::string process_ok = "arc established";
    // ... and its loss during the run: "arc lost", "blade speed lost".
    std::string process_lost = "arc lost";
    WorkCount counts = WorkCount::PathPoints;
    // Whether the run follows a path of MotionProgram::length_mm (torch machines): the stop
    // line and the summary give the length cut.
    bool path_length = true;
    // Pieces: the length of each piece in the order they are cut (the queue as planned).
    std::vector<double> piece_lengths_mm;
};

} // namespace cutcell
