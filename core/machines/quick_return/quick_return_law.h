#pragma once
// The quick-return cutter's control law, run in the engine cycle (MotionSourceKind::ControlLaw):
// one torque-mode crank axis (rad, N m) and the slider's linear scale (sensor, mm). The slider
// velocity is rho_y(q) q' from the crank encoder (the scale's 85 um steps are too coarse to
// differentiate at 1 kHz).
//   Tracking  (experiment 1): y_d = offset + amplitude sin(omega t), the chosen controller.
//   Cut       (experiment 2): Algorithm 1's profile from the top singular point, the chosen
//             controller; the Jacobian compensator (Eq. 33) maps the slider force to torque.
//   Return    open loop: +return_torque_1 until the slider passes mid-stroke, then
//             return_torque_2, until the crank passes the top singular point (next cut).
// Switching criterion (Fig. 4, made robust): the stroke is told by the sign of y'/q' = rho_y(q)
// at the measured crank angle, compared with the cut's sign found offline; the printed
// criterion y_min < y < y_max is empty since the seed's y_max < y_min.
// Stops (feed hold, abort, category-1 stop): the crank is braked to rest (AtRest). An invalid
// scale reading is a fault (no torque).
#include "core/engine/motion_source.h"
#include "core/machines/quick_return/crank_plant.h"
#include "core/machines/quick_return/task_controllers.h"
#include "core/machines/quick_return/velocity_profile.h"
#include "core/machines/quick_return/whitworth.h"

#include <array>

namespace cutcell::quick_return {

enum class Experiment { Tracking, Cutting };
const char* toString(Experiment e);

struct QuickReturnLawConfig {
    int axis = 0, sensor = 0;
    WhitworthDims dims;
    StrokeInfo stroke;       // strokeInfo(dims)
    VelocityProfile profile; // Algorithm 1 on the stroke
    Experiment experiment = Experiment::Cutting;
    ControllerKind controller = ControllerKind::Osmc;
    ControllerParams gains;
    bool jacobian_compensator = true; // Eq. 33; false: the model Jacobian rho_y (Eq. 11)
    double k_rho = 0.2;               // m/rad, compensator gain
    // Experiment 1
    double track_offset = -0.2, track_amplitude = -0.2, track_omega = 3.14159265358979;
    double track_duration = 10; // s
    // Experiment 2
    int strokes = 3;
    double return_torque_1 = 8.65, return_torque_2 = -8; // N m
    // A cut that has not reached the bottom this long after its profile ended is a fault.
    double cut_timeout = 1.0; // s
    // Hold (Track requests) and braking: a crank PD scaled by the nominal model's inertia M(q)
    // with its weight term fed forward (holdTorque), bandwidth hold_bandwidth, lowered at long
    // periods so that the derivative term changes the speed by at most kHoldStepGain of itself
    // per cycle: the loop then stays stable with the feedback several cycles late, as over a
    // CAN bus where the drive answers the SYNC after the command went out.
    CrankPlantParams model;     // nominal inertias, slider mass, gravity
    double hold_bandwidth = 40; // rad/s
    double rest_speed = 0.02;   // rad/s
    int rest_cycles = 20;
    double torque_limit = 120; // N m (the law's own clamp)
};

// Largest per-cycle derivative gain 2 w T of the hold: a velocity loop whose feedback is d
// cycles late is stable below 2 sin(pi / (2 (2d + 1))), which is above 0.2 up to d = 7.
inline constexpr double kHoldStepGain = 0.2;
// The hold's bandwidth (rad/s) at a period.
double holdBandwidth(const QuickReturnLawConfig& c, double period_s);
// Crank torque (N m) that holds q at qRef: M(q) (w^2 e + 2 w e') plus the slider's weight.
double holdTorque(const QuickReturnLawConfig& c, double q, double dq, double qRef, double dqRef,
                  double period_s);

enum class QrPhase : std::uint8_t { Hold, Tracking, Cut, ReturnPush, ReturnBrake, Braking, Done };
const char* toString(QrPhase p);

// What the law computed this cycle (for the offline experiments and plots).
struct QrSample {
    double t = 0, y = 0, dy = 0, y_d = 0, dy_d = 0, u = 0, torque = 0;
    QrPhase phase = QrPhase::Hold;
};

class QuickReturnLaw : public MotionSource {
  public:
    explicit QuickReturnLaw(const QuickReturnLawConfig& c);
    void start(const SourceInput& in) override;
    void update(const SourceInput& in, SourceOutput& out) override;
    const char* stateName() const override { return toString(phase_); }
    QrPhase phase() const { return phase_; }
    int strokesDone() const { return strokes_; }
    const QrSample& last() const { return last_; }
    const QuickReturnLawConfig& config() const { return c_; }
    // Crank angle on the cutting branch where the slider reads y (scale, m); bisection.
    double crankForSlider(double y) const;
    // True when q is on the cutting branch (q_top .. q_bottom in increasing q).
    bool onCutBranch(double q) const;

  private:
    // The crank's angle and speed n cycles after its feedback was sampled (n up to
    // kPredictCycles): the torques already written and not yet acting, with the load (contact
    // force, friction, the mechanism's speed terms) that moved it over the last fresh cycles.
    struct CrankState {
        double q = 0, dq = 0;
    };
    CrankState predictCrank(double q, double dq, double T, int n) const;
    // Nominal crank acceleration under torque tau at q: (tau - weight) / M(q).
    double nominalAcceleration(double q, double tau) const;
    double controlTorque(double q, double y, double dy, double yd, double dyd, double ddyd,
                         double T, double tSince, double* u);
    // A feed hold's rest: braking at q, then on in `resume` at the Resume.
    void holdAtRest(double q, QrPhase resume);
    QuickReturnLawConfig c_;
    TaskController ctl_;
    QrPhase phase_ = QrPhase::Hold;
    double t0_ = 0, now_ = 0, brakeAt_ = 0;
    int strokes_ = 0, rest_ = 0;
    bool restarted_ = false;
    bool holdPending_ = false; // a feed hold waits for the end of the cut or of the return
    bool held_ = false;        // braking for a feed hold: Resume goes on in resumePhase_
    QrPhase resumePhase_ = QrPhase::ReturnPush;
    double heldAt_ = 0; // s into the tracking experiment when it was held
    QrSample last_;
    // Last cycles' outputs and feedback for predictCrank: the torques written (tauHist_[0]
    // the last cycle's), the crank at the last cycle.
    static constexpr int kPredictCycles = 8;
    std::array<double, kPredictCycles + 1> tauHist_{};
    double qPrev_ = 0, dqPrev_ = 0, nowPrev_ = 0;
    double loadAcc_ = 0; // rad/s^2, low-passed
    int prevAge_ = 0;
    static constexpr double kLoadFilterS = 0.005;
    bool havePrev_ = false;
};

} // namespace cutcell::quick_return
