#include "core/engine/run_terms.h"

namespace cutcell {

const char* toString(WorkCount w) {
    switch (w) {
    case WorkCount::PathPoints:
        return "path_points";
    case WorkCount::Pieces:
        return "pieces";
    case WorkCount::Strokes:
        return "strokes";
    }
    return "path_points";
}

const char* unitSingular(WorkCount w) {
    switch (w) {
    case WorkCount::PathPoints:
        return "point";
    case WorkCount::Pieces:
        return "piece";
    case WorkCount::Strokes:
        return "stroke";
    }
    return "point";
}

const char* madeNounPlural(WorkCount w) {
    switch (w) {
    case WorkCount::PathPoints:
        return "pierces";
    case WorkCount::Pieces:
        return "pieces";
    case WorkCount::Strokes:
        return "strokes";
    }
    return "pierces";
}

} // namespace cutcell
