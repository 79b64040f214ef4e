#pragma once
// The flying saw's motion source (MotionSourceKind::MasterAxis): the carriage follows the line
// measured by the roller encoder (sensor 0, through the engine's MasterFilter), the turntable
// and both radial feeds run the saw's cycle with the cam table of the turntable angle.
//
// One cut k at the master's sync position S_k (MC_GearInPos semantics: the carriage is at its
// sync position x_w + d1/2 with the line's velocity and acceleration when the master is at S_k):
//   Waiting (AB) at the wait position until m >= S_k - d1;
//   Accelerating (BC) and InSync (CE, the saw's cycle from the moment of sync), Decelerating
//   (EF) over d3 of master travel once the saw is clear, Returning (FG-GH-HI) in time back to
//   the wait position exactly (tracking_profile.h);
//   then the next piece: S_{k+1} = S_k + (length + kerf) * scale, taken when the carriage is
//   back: the queue's next length (a queue published while running applies from the next
//   piece) and the scale corrected from the length gauge (reportGauge()).
// Axes: 0 carriage (mm), 1 turntable (rad; turns on by half a turn per cut), 2 and 3 the radial
// feeds of blades 1 and 2 (mm).
//
// Requests: FeedHold finishes the cut and the return, then rests waiting; Resume waits for a
// sync position still ahead. Abort and a controlled stop bring every axis from its velocity to
// rest in decel_s (tool off); a Run after that goes back to the wait positions in recover_s.
//
// Threading: the engine thread calls start()/update(); queue().beginWrite()/publish() and
// reportGauge() from one other thread each; the getters are for the engine thread (or after).
#include "core/engine/cam_table.h"
#include "core/engine/master_filter.h"
#include "core/engine/motion_source.h"
#include "core/machines/flying_saw/saw_cycle.h"
#include "core/machines/flying_saw/tracking_profile.h"

#include <atomic>
#include <cmath>
#include <cstdint>

namespace cutcell {

struct PieceQueue {
    static constexpr int kCapacity = 16;
    struct Entry {
        double length_mm = 0;
        int count = 0;
    };
    std::array<Entry, kCapacity> entries{};
    int size = 0;
    int total() const;
};

struct FlyingSawConfig {
    int master_sensor = 0;
    double filter_alpha = 0.2;
    ForwardStroke forward;
    SawCycle saw;
    CarriageLimits limits;
    double wait_position_mm = 0;
    double kerf_mm = 0;
    PieceQueue queue;
    double first_sync = NAN; // S_0 (master mm); NaN: the master at start + d1 + lead
    double first_sync_lead = 50;
    double decel_s = 0.3;
    double recover_s = 2;
    double gauge_gain = 1;
};

enum class SawPhase : std::uint8_t {
    Waiting,
    Accelerating,
    InSync,
    Decelerating,
    Returning,
    Stopping,
    Recovering,
    Done
};
const char* toString(SawPhase p);

class FlyingSawSource : public MotionSource {
  public:
    static constexpr int kRing = 64; // pieces remembered for the gauge and the meter
    explicit FlyingSawSource(const FlyingSawConfig& config);

    void start(const SourceInput& in) override;
    void update(const SourceInput& in, SourceOutput& out) override;
    const char* stateName() const override { return toString(phase_); }

    // Another thread: replace the rest of the queue (from the next piece), the gauge's
    // measured length of piece `piece` (1-based).
    CycleDoubleBuffer<PieceQueue>& queue() { return queue_; }
    void reportGauge(int piece, double measured_mm);

    // Engine thread / after the run.
    SawPhase phase() const { return phase_; }
    bool bladeInWall() const;
    // The cut in progress or last begun: 0 = the head cut, k = the cut that ends piece k;
    // -1 before the first.
    int cutIndex() const { return cut_; }
    int cutsDone() const { return cutsDone_; }
    double syncPosition() const { return sync_; }
    double firstSync() const { return firstSync_; }
    double scale() const { return scale_; }
    double orderedLength(int piece) const { return ordered_[ring(piece)]; }
    double pitchMaster(int piece) const { return pitch_[ring(piece)]; }
    int totalPieces() const { return total_; }
    const MasterFilter& filter() const { return filter_; }
    double carriageSyncPosition() const { return cfg_.wait_position_mm + cfg_.forward.d1 / 2; }

  private:
    static int ring(int piece) { return ((piece % kRing) + kRing) % kRing; }
    bool nextPiece(double* length);
    void takeGauge();
    void beginRecover(const SourceInput& in);

    FlyingSawConfig cfg_;
    MasterFilter filter_;
    CycleDoubleBuffer<PieceQueue> queue_;
    PieceQueue current_;
    int entry_ = 0, entryDone_ = 0, total_ = 0;
    SawPhase phase_ = SawPhase::Waiting;
    double sync_ = 0, firstSync_ = 0;
    int cut_ = -1, cutsDone_ = 0, committed_ = 0; // committed_: pieces given a length
    bool atRest_ = true, restAfterReturn_ = false;
    double tSync_ = 0, mE_ = 0, xE_ = 0, xF_ = 0, tF_ = 0, turnBase_ = 0;
    ReverseProfile reverse_;
    double scale_ = 1;
    std::array<double, kRing> ordered_{}, pitch_{};
    std::atomic<std::uint64_t> gaugeSeq_{0};
    std::atomic<int> gaugePiece_{0};
    std::atomic<double> gaugeMeasured_{0};
    std::uint64_t gaugeTaken_ = 0;
    JointVector pos_ = JointVector::Zero(), vel_ = JointVector::Zero();
    JointVector decelRate_ = JointVector::Zero();
    JointVector recFrom_ = JointVector::Zero(), recTo_ = JointVector::Zero();
    double recSince_ = 0;
    double tauNow_ = 0;
};

} // namespace cutcell
