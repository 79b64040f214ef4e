#pragma once
// The flying saw's cut-length figures, the same on every cell: each cycle a cut position on the
// pipe (q = carriage - line, mm) goes into the CutLengthMeter while the source's blade is in the
// wall; every closed cut ends a piece, whose length the simulated length gauge after the saw
// reports to the source (`gauge_delay_pieces` later) to correct its scale. The simulated rig
// feeds it the true positions, the CAN cell the positions its own instruments read over the bus
// (flying_saw_can_meter.cpp). Report: "cut_lengths" (per piece, mean, std, max, Cpk) and the
// summary line.
//
// Threading: feed() on the engine thread (allocation-free once built); the rest after the run.
#include "core/json/json.h"
#include "core/machines/flying_saw/cut_length_meter.h"
#include "core/machines/flying_saw/flying_saw_source.h"
#include "core/machines/flying_saw/flying_saw_spec.h"

#include <string>
#include <vector>

namespace cutcell {

class SawCutRecorder {
  public:
    SawCutRecorder(const FlyingSawSpec& spec, FlyingSawSource* source);
    // One sample of this cycle: the cut position on the pipe (carriage - line, mm).
    void feed(double q, double now_s);
    std::vector<PieceRecord> pieces() const;
    void addToReport(json::Value& doc) const;
    std::string summary(const std::string& outcome) const;

  private:
    FlyingSawSpec spec_;
    FlyingSawSource* source_;
    CutLengthMeter meter_;
    std::vector<double> gauge_, ordered_;
    size_t seen_ = 0;
};

} // namespace cutcell
