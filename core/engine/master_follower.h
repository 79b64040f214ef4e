#pragma once
// Motion parameterised by a master axis the engine does not drive (a pipe line measured by an
// encoder on a measuring roller): PLCopen MC_GearInPos and MC_CamIn, with the flying saw's
// repeating cut cycle around them.
//
// One cut cycle k (sync position S_k of the master, filtered):
//   Waiting        the coupled axes stand at their wait positions until the master reaches
//                  S_k - start_distance;
//   Synchronizing  over start_distance of master travel every coupled axis blends from its wait
//                  position into its coupling: x = w + (c(m) - w) * s(u), u = (m - S_k + D) / D,
//                  s the quintic smoothstep, so it leaves at rest and arrives with the
//                  coupling's position, velocity and acceleration at m = S_k exactly;
//   InSync         x = c(m): gear c = slave_sync + ratio * (m - S_k), cam c = table(m - S_k)
//                  + offset; the process tool does its work (a saw feeds in by its cam);
//   Returning      after sync_span of master travel (0 = coupled until the program ends) the
//                  axes leave the line with a quintic in time from their position and velocity
//                  to the wait positions in return_s;
//   then S_{k+1} = S_k + cut length (the length in effect when cycle k ends: it may be changed
//   while running, setCutLength()), until cut_count cuts are done.
// A cam table replaced while running (camTables()) is taken at the next cam-cycle boundary of
// the master (m - S_k crossing a multiple of the table's period), or at once while waiting.
//
// Requests: FeedHold finishes the current cut and the return, then stays at rest waiting
// (AtRest); Resume waits for the next sync position still ahead of the master. Abort and a
// controlled stop leave the line at once: the axes decelerate from their coupled velocity to
// rest in decel_s (tool off), then AtRest. The override does not apply: the line sets the
// speed. A master reading that is not valid is a fault.
#include "core/engine/cam_table.h"
#include "core/engine/master_filter.h"
#include "core/engine/motion_source.h"

#include <atomic>
#include <memory>

namespace cutcell {

enum class CouplingKind : std::uint8_t { None, Gear, Cam };

struct AxisCoupling {
    CouplingKind kind = CouplingKind::None;
    double ratio = 1;      // Gear: slave units per master unit
    double slave_sync = 0; // Gear: slave position at the sync position of the master
    double cam_offset = 0; // Cam: added to the table's value
    int cam = 0;           // Cam: which table (0 .. kMaxCams - 1)
};

enum class SyncState : std::uint8_t { Waiting, Synchronizing, InSync, Returning, Stopping, Done };
const char* toString(SyncState s);

struct MasterFollowerConfig {
    static constexpr int kMaxCams = 2;
    int master_sensor = 0; // index into EngineDevices::sensors
    double filter_alpha = 0.2;
    double filter_beta = 0; // 0: Benedict-Bordner from alpha
    std::array<AxisCoupling, kMaxAxes> couplings{};
    JointVector wait_position = JointVector::Zero(); // also the program's start position
    double first_sync = 0;                           // S_0, master units
    double cut_length = 0;      // S_{k+1} - S_k (master units); 0 = a single cycle
    double start_distance = 50; // D: master travel of the sync-in
    double sync_span = 0;       // master travel in sync per cut; 0 = until the program ends
    double return_s = 1;        // duration of the return to the wait positions
    double decel_s = 0.5;       // abort / stop: coupled velocity to rest
    int cut_count = 1;
    bool tool_in_sync_only = false; // tool on only while in sync (else for the whole program)
};

class MasterFollower : public MotionSource {
  public:
    explicit MasterFollower(const MasterFollowerConfig& config);

    void start(const SourceInput& in) override;
    void update(const SourceInput& in, SourceOutput& out) override;
    const char* stateName() const override { return toString(state_); }

    // Any one non-cycle thread: the cam tables (beginWrite / publish) and the cut length of
    // the cycles still to start.
    CycleDoubleBuffer<std::array<CamTable, MasterFollowerConfig::kMaxCams>>& camTables() {
        return cams_;
    }
    void setCutLength(double masterUnits) { cutLength_.store(masterUnits); }

    // Engine thread (or after the run): for telemetry and tests.
    SyncState state() const { return state_; }
    double filteredMaster() const { return filter_.position(); }
    double syncPosition() const { return sync_; }
    int cutsDone() const { return cutsDone_; }
    std::uint64_t camSwaps() const { return camSwaps_; }
    const MasterFilter& filter() const { return filter_; }

  private:
    double coupled(int axis, double m) const;
    void beginReturn(const SourceInput& in);

    MasterFollowerConfig cfg_;
    MasterFilter filter_;
    CycleDoubleBuffer<std::array<CamTable, MasterFollowerConfig::kMaxCams>> cams_;
    std::atomic<double> cutLength_{0};
    SyncState state_ = SyncState::Waiting;
    double sync_ = 0;
    long camCycle_ = 0;
    int cutsDone_ = 0;
    bool restAfterReturn_ = false; // feed hold during a cut: rest once back
    bool atRest_ = false;
    std::uint64_t camSwaps_ = 0;
    JointVector pos_ = JointVector::Zero(), vel_ = JointVector::Zero();
    // Return quintic per axis: x(s) = x0 + v0 T s + a s^3 + b s^4 + c s^5.
    JointVector retX0_ = JointVector::Zero(), retV0_ = JointVector::Zero();
    JointVector retA_ = JointVector::Zero(), retB_ = JointVector::Zero(),
                retC_ = JointVector::Zero();
    double retSince_ = 0;
    JointVector decelRate_ = JointVector::Zero();
};

} // namespace cutcell
