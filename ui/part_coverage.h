#pragma once
// Which stretches of a part's path its runs cut. A part starts with Start from the path's
// start; a stop (E-STOP, fault, abort) ends a run part way; a cut recovery goes on from a path
// time: from before the stop ("Resume from stop" with its lead-in) the path stays whole, from
// beyond it ("Run from point") the stretch in between was never cut. A part with such a gap is
// not counted as good unless the operator confirms it (RunController).
//
// Threading contract: GUI thread only (plain data).
#include <vector>

namespace CutCell::ui {

class PartCoverage {
  public:
    struct Gap {
        double from_s = 0, to_s = 0; // path time never cut
    };
    // Start from the path's start: a new part, nothing cut yet.
    void begin();
    // A cut recovery from path time `t_s`: a gap if it lies beyond what was cut.
    void recoverFrom(double t_s);
    // The run stopped at path time `t_s` (it cut the path up to there).
    void stoppedAt(double t_s);
    const std::vector<Gap>& gaps() const { return gaps_; }
    bool whole() const { return gaps_.empty(); }

  private:
    // Path time up to which the part is cut; a recovery starting up to this much beyond it
    // (the engine's own rounding to its cycle) joins.
    static constexpr double kJoinS = 1e-6;
    double reached_s_ = 0;
    std::vector<Gap> gaps_;
};

} // namespace CutCell::ui
