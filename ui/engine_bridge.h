#pragma once
// The GUI's side of the engine: a ~30 Hz timer on the GUI thread drains the engine's telemetry
// and event rings (never blocking: popTelemetry/popEvent return at once) and re-emits them as
// signals; commands are forwarded as non-blocking requests.
//
// Threading contract: GUI thread only. The engine may be swapped with setEngine() between
// ticks; the bridge never waits on the engine.
#include "core/engine/motion_engine.h"

#include <QObject>

#include <vector>

class QTimer;

namespace CutCell::ui {

class EngineBridge : public QObject {
    Q_OBJECT
  public:
    explicit EngineBridge(QObject* parent = nullptr);

    void setEngine(cutcell::MotionEngine* engine);
    cutcell::MotionEngine* engine() const { return engine_; }
    void setIntervalMs(int ms);

    // The last sample drained (valid once hasSample()).
    const cutcell::TelemetrySample& last() const { return last_; }
    bool hasSample() const { return hasSample_; }
    cutcell::EngineState state() const { return state_; }
    std::uint64_t samplesDrained() const { return drained_; }
    // Time the GUI thread spent in the last tick / the longest tick (drain + every slot).
    double lastTickMs() const { return lastTickMs_; }
    double maxTickMs() const { return maxTickMs_; }
    void resetTickStats() { maxTickMs_ = 0; }

    // Drains now (also called by the timer).
    void poll();

  signals:
    // Every sample drained in one tick, oldest first (direct connections only).
    void samples(const std::vector<cutcell::TelemetrySample>& batch);
    void event(const cutcell::EngineEvent& e);
    void stateChanged(cutcell::EngineState state);
    // The engine thread's own timing, twice a second.
    void cycleStats(const cutcell::CycleStats& stats);

  private:
    QTimer* timer_;
    QTimer* statsTimer_;
    cutcell::MotionEngine* engine_ = nullptr;
    std::vector<cutcell::TelemetrySample> batch_;
    cutcell::TelemetrySample last_{};
    bool hasSample_ = false;
    cutcell::EngineState state_ = cutcell::EngineState::Idle;
    std::uint64_t drained_ = 0;
    double lastTickMs_ = 0, maxTickMs_ = 0;
};

} // namespace CutCell::ui
