#include "ui/engine_bridge.h"

#include <QElapsedTimer>

#include <QTimer>
#include <algorithm>

namespace CutCell::ui {

namespace {
// Upper bound of samples handled per tick: the GUI stays responsive even when the engine runs
// as fast as possible (the rest stays in the ring, or is counted as dropped by the engine).
constexpr size_t kMaxPerTick = 4096;
} // namespace

EngineBridge::EngineBridge(QObject* parent)
    : QObject(parent), timer_(new QTimer(this)), statsTimer_(new QTimer(this)) {
    statsTimer_->setInterval(500);
    connect(statsTimer_, &QTimer::timeout, this, [this] {
        if (engine_) emit cycleStats(engine_->cycleStats()); // atomics only: never blocks
    });
    statsTimer_->start();
    timer_->setTimerType(Qt::PreciseTimer);
    timer_->setInterval(33);
    connect(timer_, &QTimer::timeout, this, &EngineBridge::poll);
    batch_.reserve(kMaxPerTick);
    timer_->start();
}

void EngineBridge::setEngine(cutcell::MotionEngine* engine) {
    engine_ = engine;
    hasSample_ = false;
    last_ = cutcell::TelemetrySample{};
    const auto s = engine_ ? engine_->state() : cutcell::EngineState::Idle;
    if (s != state_) {
        state_ = s;
        emit stateChanged(state_);
    }
}

void EngineBridge::setIntervalMs(int ms) {
    timer_->setInterval(ms);
}

void EngineBridge::poll() {
    if (!engine_) return;
    QElapsedTimer work;
    work.start();
    cutcell::EngineEvent e;
    while (engine_->popEvent(e))
        emit event(e);
    batch_.clear();
    cutcell::TelemetrySample s;
    while (batch_.size() < kMaxPerTick && engine_->popTelemetry(s))
        batch_.push_back(s);
    if (!batch_.empty()) {
        drained_ += batch_.size();
        last_ = batch_.back();
        hasSample_ = true;
        emit samples(batch_);
    }
    const auto st = batch_.empty() ? engine_->state() : last_.state;
    if (st != state_) {
        state_ = st;
        emit stateChanged(state_);
    }
    lastTickMs_ = static_cast<double>(work.nsecsElapsed()) / 1e6;
    maxTickMs_ = std::max(maxTickMs_, lastTickMs_);
}

} // namespace CutCell::ui
