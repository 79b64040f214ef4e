#include "ui/panels/run_words.h"
#include "ui/shown_number.h"

#include <QCoreApplication>

#include <algorithm>
#include <iterator>

namespace CutCell::ui {

using cutcell::WorkCount;

namespace {
struct RunWords {
    Q_DECLARE_TR_FUNCTIONS(RunWords)
};
// The words of each count, in the order of WorkCount (translated when shown).
struct CountWords {
    const char* caption; // the progress figure's caption
    const char* one;     // the unit counted, singular / plural
    const char* many;
    const char* madeCaption;        // the counter of what was made
    const char *madeOne, *madeMany; // what a run makes
};
constexpr CountWords kWords[] = {
    {QT_TRANSLATE_NOOP("RunWords", "Point"), QT_TRANSLATE_NOOP("RunWords", "point"),
     QT_TRANSLATE_NOOP("RunWords", "points"), QT_TRANSLATE_NOOP("RunWords", "Parts"),
     QT_TRANSLATE_NOOP("RunWords", "pierce"), QT_TRANSLATE_NOOP("RunWords", "pierces")},
    {QT_TRANSLATE_NOOP("RunWords", "Piece"), QT_TRANSLATE_NOOP("RunWords", "piece"),
     QT_TRANSLATE_NOOP("RunWords", "pieces"), QT_TRANSLATE_NOOP("RunWords", "Pieces"),
     QT_TRANSLATE_NOOP("RunWords", "piece"), QT_TRANSLATE_NOOP("RunWords", "pieces")},
    {QT_TRANSLATE_NOOP("RunWords", "Stroke"), QT_TRANSLATE_NOOP("RunWords", "stroke"),
     QT_TRANSLATE_NOOP("RunWords", "strokes"), QT_TRANSLATE_NOOP("RunWords", "Strokes"),
     QT_TRANSLATE_NOOP("RunWords", "stroke"), QT_TRANSLATE_NOOP("RunWords", "strokes")},
};
const CountWords& wordsOf(WorkCount w) {
    const auto i = static_cast<size_t>(w);
    return kWords[i < std::size(kWords) ? i : 0];
}
} // namespace

QString countCaption(WorkCount w) {
    return RunWords::tr(wordsOf(w).caption);
}

QString countNoun(WorkCount w, long n) {
    return RunWords::tr(n == 1 ? wordsOf(w).one : wordsOf(w).many);
}

QString madeCaption(WorkCount w) {
    return RunWords::tr(wordsOf(w).madeCaption);
}

QString madeNoun(WorkCount w, long n) {
    return RunWords::tr(n == 1 ? wordsOf(w).madeOne : wordsOf(w).madeMany);
}

QString toolWord(const cutcell::RunTerms& terms) {
    const std::string& t = terms.tool;
    if (t == "torch") return RunWords::tr("torch");
    if (t == "saw") return RunWords::tr("saw");
    if (t == "cutter") return RunWords::tr("cutter");
    return QString::fromStdString(t);
}

QString stateWord(cutcell::EngineState s) {
    using cutcell::EngineState;
    switch (s) {
    case EngineState::Idle:
        return RunWords::tr("Idle");
    case EngineState::Ready:
        return RunWords::tr("Ready");
    case EngineState::Homing:
        return RunWords::tr("Homing");
    case EngineState::Jogging:
        return RunWords::tr("Jogging");
    case EngineState::Running:
        return RunWords::tr("Running");
    case EngineState::Paused:
        return RunWords::tr("Feed hold");
    case EngineState::Completed:
        return RunWords::tr("Completed");
    case EngineState::EmergencyStop:
        return RunWords::tr("Emergency stop");
    case EngineState::Fault:
        return RunWords::tr("Fault");
    }
    return QString::fromLatin1(cutcell::toString(s));
}

QString stopFigures(const cutcell::RunTerms& terms, const cutcell::RunStopPoint& at,
                    double pathLengthMm) {
    // The engine counts from 0 what is done; the operator reads "n of N" of the one in work.
    const auto shown = at.point_count ? std::min(at.point_index + 1, at.point_count) : 0u;
    if (terms.counts == WorkCount::PathPoints && terms.path_length)
        return RunWords::tr("point %1 / %2, %3 of %4 mm")
            .arg(shown)
            .arg(at.point_count)
            .arg(shownNumber(at.length_mm, 1))
            .arg(shownNumber(pathLengthMm, 1));
    return RunWords::tr("%1 %2 of %3, %4 %5 made")
        .arg(countNoun(terms.counts, 1))
        .arg(shown)
        .arg(at.point_count)
        .arg(at.made)
        .arg(madeNoun(terms.counts, at.made));
}

} // namespace CutCell::ui
