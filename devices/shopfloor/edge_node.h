#pragma once
// The Sparkplug B edge node of one cell: the session rules of the specification (birth and
// death certificates, bdSeq, seq, rebirth, aliases, store and forward) over any transport that
// can publish, subscribe and hold a will. It knows nothing of MQTT libraries or threads: the
// transport (MosquittoLink, or a fake in the tests) calls it one call at a time and it answers
// by publishing through the transport. Nothing here waits for the network.
//
// Topics: spBv1.0/<group_id>/{NBIRTH,NDATA,NDEATH,NCMD}/<edge_node_id>.
// - NDEATH is the session's MQTT will and carries bdSeq; NBIRTH carries the same bdSeq, seq 0 and
//   every metric with its name, alias and datatype. bdSeq counts sessions (0..255, wrapping):
//   it steps after each session that reached its CONNACK, so the next will differs.
// - NDATA: the metrics whose values changed, by alias only, seq 1..255 then 0 again. What moves
//   continuously (axis data, the job's progress) at most axis_rate_hz; everything else as soon
//   as it changes.
// - While there is no session the changes are kept in a bounded queue (oldest dropped first,
//   drops counted) and sent after the next NBIRTH, in order, flagged is_historical.
// - NCMD: Node Control/Rebirth, Queue Job, Feed Hold, Clear Queue; anything else is refused and
//   the refusal is published as Node Control/Last Command Result.
#include "core/shopfloor/cell_snapshot.h"
#include "core/shopfloor/shopfloor_command_sink.h"
#include "devices/shopfloor/sparkplug_payload.h"

#include <cstdint>
#include <deque>
#include <functional>
#include <string>
#include <vector>

namespace cutcell::shopfloor {

class SparkplugTransport {
  public:
    virtual ~SparkplugTransport() = default;
    // Hands the bytes over without waiting for the network; false when they cannot go now (no
    // session): the node then keeps them for the next session.
    virtual bool publish(const std::string& topic, const std::string& bytes, int qos,
                         bool retain) = 0;
    virtual bool subscribe(const std::string& topic, int qos) = 0;
    // The will of the next CONNECT (the current session's is fixed at its CONNECT).
    virtual void setWill(const std::string& topic, const std::string& bytes, int qos,
                         bool retain) = 0;
};

struct EdgeNodeOptions {
    std::string group_id;
    std::string edge_node_id;
    double axis_rate_hz = 10;                   // axis metrics at most this often
    std::size_t store_forward_capacity = 10000; // NDATA kept while there is no session
    std::string command_source = "shop floor (Sparkplug NCMD)"; // given to queueJob()
    std::function<void(const std::string&)> log; // refusals and dropped values, one line each
    std::function<std::uint64_t()> clock_ms;     // wall clock, ms since the epoch (tests inject)
};

// The metrics every cell publishes, with their fixed aliases (README.md has the table). Axis n
// (1-based) adds Axes/<n>/Name, Position and Following Error at aliases kAxisAliasBase +
// 10 * (n - 1) + 0, 1, 2. bdSeq is published by name only (NBIRTH and NDEATH).
struct MetricInfo {
    const char* name;
    std::uint64_t alias;
    sparkplug::DataType type;
};
extern const std::vector<MetricInfo> kCellMetrics;
inline constexpr std::uint64_t kAxisAliasBase = 100;
inline constexpr std::size_t kMaxAxes = 64;

inline constexpr const char* kRebirth = "Node Control/Rebirth";
inline constexpr const char* kQueueJob = "Node Control/Queue Job";
inline constexpr const char* kFeedHold = "Node Control/Feed Hold";
inline constexpr const char* kClearQueue = "Node Control/Clear Queue";
inline constexpr const char* kLastCommandResult = "Node Control/Last Command Result";

struct EdgeNodeStats {
    bool online = false; // a session is up and NBIRTH was sent
    int bd_seq = 0;      // of the current (or next) session
    int seq = 0;         // of the last message sent (NBIRTH: 0)
    std::uint64_t births = 0;
    std::uint64_t data_sent = 0; // NDATA handed to the transport (live and from the queue)
    std::uint64_t queued = 0;    // NDATA waiting in the store-and-forward queue now
    std::uint64_t dropped = 0;   // NDATA dropped from the full queue, since start
    std::uint64_t sessions = 0;  // sessions that reached NBIRTH
    std::uint64_t commands_accepted = 0;
    std::uint64_t commands_refused = 0;
    std::string last_command_result;
    std::string last_error; // the last refused value (NaN, Inf) or payload problem
};

class EdgeNode {
  public:
    EdgeNode(EdgeNodeOptions options, SparkplugTransport& transport,
             ShopfloorCommandSink* commands);

    // Before the first CONNECT: the will (NDEATH with the current bdSeq) is set.
    void prepareSession();
    // The broker accepted the CONNECT: subscribe to NCMD, NBIRTH, then the queue.
    void connected();
    // The session is gone (or never came): offline; after a session, bdSeq steps and the next
    // will is set.
    void disconnected();
    // A message from a subscription (NCMD).
    void message(const std::string& topic, const std::string& bytes);
    // The cell's state now: what changed goes out (or into the queue).
    void update(const CellSnapshot& snapshot);
    // The last snapshot again: sends what the rate limit held back (the transport calls this
    // every 100 ms or so, so a last axis position is not kept back when snapshots stop).
    void poll();
    // A clean end: NDEATH published by the node itself (a DISCONNECT discards the will).
    void shutdown();

    std::string topic(const std::string& type) const; // "spBv1.0/<group>/<type>/<edge>"
    const EdgeNodeStats& stats() const { return stats_; }
    // NDEATH's bytes for the current bdSeq (the will).
    std::string deathPayload() const;

  private:
    struct Pending {
        std::uint64_t timestamp_ms;
        std::vector<sparkplug::Metric> metrics; // by alias, values as they were
    };
    struct Slot {
        sparkplug::Metric metric; // name, alias, type, properties, value last published
        bool continuous = false;  // axis data and progress: rate-limited
        bool link = false;        // the link's own counters: not queued while offline
    };

    std::vector<Slot> currentMetrics(const CellSnapshot& s);
    std::uint64_t now() const;
    int nextSeq();
    void publishBirth();
    void flushQueue();
    // One NDATA with the next seq; false when the transport did not take it.
    bool transmit(std::vector<sparkplug::Metric> metrics, std::uint64_t timestamp_ms,
                  bool historical);
    // Live NDATA: sent now, or kept in the queue while there is no session.
    void sendData(std::vector<sparkplug::Metric> metrics, std::uint64_t timestamp_ms);
    void commandResult(bool accepted, const std::string& text);
    void handleCommand(const sparkplug::Metric& m);
    void note(const std::string& line);
    std::string shapeOf(const CellSnapshot& s) const;

    EdgeNodeOptions options_;
    SparkplugTransport& transport_;
    ShopfloorCommandSink* commands_;
    EdgeNodeStats stats_;
    CellSnapshot last_; // the latest snapshot (NBIRTH's values)
    bool have_snapshot_ = false;
    bool session_ = false;        // connected() came and disconnected() not yet
    std::string shape_;           // machine and axes of the last NBIRTH: a change needs a rebirth
    std::vector<Slot> published_; // the values as the host knows them (after our last message)
    std::uint64_t last_axis_ms_ = 0;
    std::deque<Pending> queue_;
};

} // namespace cutcell::shopfloor
