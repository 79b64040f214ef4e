#pragma once
// A CiA 402 drive simulator on a CAN bus: one or more DriveNodes behind one QCanBusDevice,
// a real peer on the bus (virtualcan in tests, socketcan on a real interface).
//
// Threading contract: the simulator runs on its own QThread with its own event loop; the
// QCanBusDevice and the nodes live there and are touched only there. start()/stop() may be
// called from any one controlling thread; start() waits (bounded) for the bus connection.
// Node snapshots are copied under a mutex for tests and the CLI, never for a control cycle.
#include "core/job/job.h"
#include "devices/canopen/drive_node.h"
#include "devices/canopen/encoder_node.h"

#include <QString>

#include <condition_variable>
#include <memory>
#include <mutex>
#include <vector>

class QCanBusDevice;
class QObject;
class QThread;
class QTimer;

namespace cutcell::canopen {

struct DriveSimulatorConfig {
    QString plugin = QStringLiteral("virtualcan");
    QString interface = QStringLiteral("can0");
    std::vector<DriveNodeConfig> nodes;
    std::vector<EncoderNodeConfig> encoders; // CiA 406 encoders on the same bus peer
};

struct SimNodeSnapshot {
    int node = 0;
    NmtState nmt = NmtState::Unknown;
    Cia402State state = Cia402State::Unknown;
    double position_rad = 0;
    std::uint16_t error_code = 0;
    std::uint64_t syncs = 0;
    double torque = 0;                  // applied over the last loop step (N m or N)
    std::uint64_t disabled_at_sync = 0; // SYNC count when it last left Operation Enabled
    bool encoder = false;               // a CiA 406 encoder (position_rad: its counts)
};

class DriveSimulator {
  public:
    explicit DriveSimulator(DriveSimulatorConfig config);
    ~DriveSimulator();
    DriveSimulator(const DriveSimulator&) = delete;
    DriveSimulator& operator=(const DriveSimulator&) = delete;

    // Connects to the bus and boots every node. False (with errorText()) when the plugin or
    // interface cannot be opened or the connection does not come up within timeout_ms.
    bool start(int timeout_ms = 3000);
    void stop();
    QString errorText() const;
    // Fault injection on the simulator thread (queued; returns at once): node raises EMCY
    // `code` and enters Fault / stops producing heartbeats.
    void injectFault(int node, std::uint16_t code);
    void stopHeartbeat(int node); // drive or encoder
    void stopPdo(int node);       // an encoder's TPDOs stop (frozen on a live node)
    std::vector<SimNodeSnapshot> snapshot() const;
    std::uint64_t framesReceived() const;

  private:
    void openOnThread(); // runs on the simulator thread
    void closeOnThread();
    void onFramesReceived();
    void onTick();
    void send(const std::vector<CanFrame>& frames);
    void publish();
    double now() const;

    DriveSimulatorConfig config_;
    std::unique_ptr<QThread> thread_;
    QObject* context_ = nullptr;      // lives on thread_: target of queued calls
    QCanBusDevice* device_ = nullptr; // owned by the simulator thread
    QTimer* tick_ = nullptr;
    double lastTick_s_ = -1;    // [sim thread]
    bool tickDeferred_ = false; // [sim thread] the last tick judged nothing after a stall
    std::vector<DriveNode> nodes_;
    std::vector<EncoderNode> encoders_;
    std::vector<CanFrame> out_;
    qint64 startNs_ = 0;

    mutable std::mutex mutex_; // guards the fields below
    std::condition_variable changed_;
    QString error_;
    bool connected_ = false;
    bool failed_ = false;
    std::vector<SimNodeSnapshot> snapshot_;
    std::uint64_t framesReceived_ = 0;
};

} // namespace cutcell::canopen
