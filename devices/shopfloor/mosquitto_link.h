#pragma once
// The shop-floor link on libmosquitto (Debian libmosquitto-dev): TLS to the broker with its
// certificate checked against the configured CA (optional client certificate), user name and
// password, the edge node's NDEATH as the MQTT will, reconnection with back-off, and the
// EdgeNode (edge_node.h) driven from here.
//
// Threads: the link runs its own network thread (mosquitto_loop on it). Every call into the
// EdgeNode, from that thread's callbacks or from submit(), holds the link's node mutex, so the
// node sees one call at a time. submit() never waits for it: when the node is busy (a
// store-and-forward queue being sent after a reconnection) the snapshot is parked in a
// one-snapshot mailbox (the newest wins) and whichever thread holds the node next takes it.
// status() and stats() read copies and never wait for the node either. Nothing here runs in
// the engine's cycle.
#include "core/shopfloor/cell_snapshot.h"
#include "core/shopfloor/shopfloor_command_sink.h"
#include "devices/shopfloor/edge_node.h"
#include "devices/shopfloor/shopfloor_config.h"

#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

struct mosquitto;
struct mosquitto_message;

namespace cutcell::shopfloor {

enum class LinkState {
    Off,          // not started (or the configuration says enabled: false)
    Connecting,   // a CONNECT is under way
    Connected,    // the broker accepted us; NBIRTH sent
    Reconnecting, // the connection failed or was lost; waiting to try again
    Refused,      // the broker refused the CONNECT (user, password, ACL); retried
    TlsError,     // the TLS handshake failed (certificate not trusted, ...); retried
    Stopped,      // stop() ran
};
const char* toString(LinkState s);

struct LinkStatus {
    LinkState state = LinkState::Off;
    std::string text; // for the status bar: "connected to host:port", "refused: not authorised"
    int attempt = 0;  // CONNECT attempts since the last accepted one
};

// A CONNECT attempt that has no CONNACK after this long is given up (and retried after the
// back-off): a broker that takes longer to answer a TLS handshake is not usable anyway.
inline constexpr double kConnectTimeoutS = 10;

// Whether the socket of a CONNECT under way is already gone (refused, reset): its error (the
// socket's, else ECONNRESET), 0 while it lives. libmosquitto 2.0.11 under TLS does not notice a
// refused connect itself (see MosquittoLink::run).
int socketHungUp(int fd);

struct MosquittoLinkOptions {
    double reconnect_min_s = 1;  // the first retry's delay, doubled each failure ...
    double reconnect_max_s = 30; // ... up to this
    std::function<void(const std::string&)> log;
    std::function<std::uint64_t()> clock_ms; // for the node (tests); default the system clock
};

class MosquittoLink final : private SparkplugTransport {
  public:
    MosquittoLink(ShopfloorConfig config, ShopfloorCommandSink* commands,
                  MosquittoLinkOptions options = {});
    ~MosquittoLink() override;
    MosquittoLink(const MosquittoLink&) = delete;
    MosquittoLink& operator=(const MosquittoLink&) = delete;

    // Reads the password file, sets up TLS and the will, starts the network thread. false and
    // *error when the configuration cannot work (a file missing, a disabled configuration).
    bool start(std::string* error);
    // NDEATH published (a clean DISCONNECT makes the broker drop the will), then disconnect
    // and join the thread. Idempotent.
    void stop();

    // The cell's state now; returns at once (see the threads note above).
    void submit(const CellSnapshot& snapshot);

    LinkStatus status() const;
    EdgeNodeStats stats() const;

  private:
    bool publish(const std::string& topic, const std::string& bytes, int qos, bool retain) override;
    bool subscribe(const std::string& topic, int qos) override;
    void setWill(const std::string& topic, const std::string& bytes, int qos, bool retain) override;

    static void onConnect(mosquitto*, void* self, int rc);
    static void onDisconnect(mosquitto*, void* self, int rc);
    static void onMessage(mosquitto*, void* self, const mosquitto_message* msg);
    static void onPublish(mosquitto*, void* self, int mid);
    static void onLog(mosquitto*, void* self, int level, const char* text);

    void run();
    void sessionEnded(int rc, int err);
    bool pause(double seconds);
    void setStatus(LinkState s, std::string text);
    std::string where() const;
    template <typename F> void withNode(F&& f);
    void drainMailbox();

    ShopfloorConfig config_;
    MosquittoLinkOptions options_;
    mosquitto* mosq_ = nullptr;
    std::thread thread_;
    std::atomic<bool> stopping_{false};
    std::atomic<bool> started_{false};

    std::mutex node_mutex_; // one call at a time into node_
    EdgeNode node_;

    std::mutex mailbox_mutex_;
    std::optional<CellSnapshot> mailbox_;
    std::atomic<bool> mailbox_full_{false};

    mutable std::mutex status_mutex_; // status_ and stats_ copies
    LinkStatus status_;
    EdgeNodeStats stats_;

    std::mutex wait_mutex_; // back-off sleep and the wait for the NDEATH to leave
    std::condition_variable wake_;
    int death_mid_ = -1;
    bool death_sent_ = false;

    int attempt_ = 0;       // network thread only
    bool accepted_ = false; // network thread only: CONNACK 0 in this attempt
    std::string tls_error_; // network thread only: the last OpenSSL error logged
};

} // namespace cutcell::shopfloor
