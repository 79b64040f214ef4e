// The shop-floor link on libmosquitto (mosquitto_link.h).
#include "devices/shopfloor/mosquitto_link.h"

#include <mosquitto.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

namespace cutcell::shopfloor {
namespace {

// The MQTT 3.1.1 CONNACK return codes in the status bar's words.
std::string refusal(int rc) {
    switch (rc) {
    case 1:
        return "refused: unacceptable protocol version";
    case 2:
        return "refused: client identifier rejected";
    case 3:
        return "refused: broker unavailable";
    case 4:
        return "refused: bad user name or password";
    case 5:
        return "refused: not authorised";
    default:
        return "refused: CONNACK code " + std::to_string(rc);
    }
}

// A key file with a passphrase would make OpenSSL prompt on the terminal (and hang a GUI):
// give it no passphrase, so loading fails with a message instead.
int noPassphrase(char*, int, int, void*) {
    return 0;
}

EdgeNodeOptions nodeOptions(const ShopfloorConfig& c, const MosquittoLinkOptions& o) {
    EdgeNodeOptions n;
    n.group_id = c.group_id;
    n.edge_node_id = c.edge_node_id;
    n.axis_rate_hz = c.axis_rate_hz;
    n.store_forward_capacity = static_cast<std::size_t>(c.store_forward_capacity);
    n.log = o.log;
    n.clock_ms = o.clock_ms;
    return n;
}

} // namespace

const char* toString(LinkState s) {
    switch (s) {
    case LinkState::Off:
        return "off";
    case LinkState::Connecting:
        return "connecting";
    case LinkState::Connected:
        return "connected";
    case LinkState::Reconnecting:
        return "reconnecting";
    case LinkState::Refused:
        return "refused";
    case LinkState::TlsError:
        return "TLS error";
    case LinkState::Stopped:
        return "stopped";
    }
    return "?";
}

MosquittoLink::MosquittoLink(ShopfloorConfig config, ShopfloorCommandSink* commands,
                             MosquittoLinkOptions options)
    : config_(std::move(config)), options_(std::move(options)),
      node_(nodeOptions(config_, options_), *this, commands) {
    status_.text = "shop-floor link off";
}

MosquittoLink::~MosquittoLink() {
    stop();
    if (mosq_) mosquitto_destroy(mosq_);
}

std::string MosquittoLink::where() const {
    return config_.host + ":" + std::to_string(config_.port);
}

void MosquittoLink::setStatus(LinkState s, std::string text) {
    bool changed = false;
    {
        std::lock_guard lock(status_mutex_);
        changed = text != status_.text;
        status_.state = s;
        status_.text = text;
        status_.attempt = attempt_;
    }
    if (changed && options_.log) options_.log("shop-floor link: " + text);
}

LinkStatus MosquittoLink::status() const {
    std::lock_guard lock(status_mutex_);
    return status_;
}

EdgeNodeStats MosquittoLink::stats() const {
    std::lock_guard lock(status_mutex_);
    return stats_;
}

template <typename F> void MosquittoLink::withNode(F&& f) {
    {
        std::lock_guard lock(node_mutex_);
        f();
        std::lock_guard s(status_mutex_);
        stats_ = node_.stats();
    }
    drainMailbox(); // a snapshot parked while we held the node
}

void MosquittoLink::drainMailbox() {
    // Whoever holds the node mutex takes the parked snapshot after its own work; a submit()
    // that finds the mutex taken only parks. Every holder drains after unlocking, so a parked
    // snapshot never waits for the next submit().
    while (mailbox_full_.load()) {
        std::unique_lock lock(node_mutex_, std::try_to_lock);
        if (!lock.owns_lock()) return;
        std::optional<CellSnapshot> s;
        {
            std::lock_guard m(mailbox_mutex_);
            s.swap(mailbox_);
            mailbox_full_ = false;
        }
        if (s) node_.update(*s);
        std::lock_guard st(status_mutex_);
        stats_ = node_.stats();
    }
}

void MosquittoLink::submit(const CellSnapshot& snapshot) {
    {
        std::lock_guard m(mailbox_mutex_);
        mailbox_ = snapshot;
        mailbox_full_ = true;
    }
    drainMailbox();
}

bool MosquittoLink::start(std::string* error) {
    auto refuse = [&](const std::string& why) {
        if (mosq_) mosquitto_destroy(mosq_); // a later start() begins afresh
        mosq_ = nullptr;
        if (error) *error = why;
        setStatus(LinkState::Off, "shop-floor link off: " + why);
        return false;
    };
    if (started_) return true;
    if (!config_.enabled) return refuse("the configuration says enabled: false");
    std::string password;
    try {
        checkShopfloorConfig(config_);
        if (!config_.password_file.empty())
            password = readPasswordFile(config_.resolve(config_.password_file));
    } catch (const ShopfloorConfigError& e) {
        return refuse(e.what());
    }
    const std::string ca = config_.resolve(config_.tls.ca_file);
    const std::string cert = config_.resolve(config_.tls.cert_file);
    const std::string key = config_.resolve(config_.tls.key_file);
    for (const auto& [k, f] : {std::pair<const char*, const std::string&>{"tls.ca_file", ca},
                               {"tls.cert_file", cert},
                               {"tls.key_file", key}})
        if (!f.empty() && ::access(f.c_str(), R_OK) != 0)
            return refuse(std::string(k) + " " + f + ": " + std::strerror(errno));

    static std::once_flag init;
    std::call_once(init, [] { mosquitto_lib_init(); }); // once per process, never cleaned up
    const std::string id = "cutcell-" + config_.group_id + "-" + config_.edge_node_id;
    mosq_ = mosquitto_new(id.c_str(), true, this); // clean session: Sparkplug requires it
    if (!mosq_) return refuse("mosquitto_new failed");
    mosquitto_int_option(mosq_, MOSQ_OPT_PROTOCOL_VERSION, MQTT_PROTOCOL_V311);
    // Publishing from the caller's thread only queues the packet; the network thread writes.
    mosquitto_threaded_set(mosq_, true);
    int rc = mosquitto_tls_set(mosq_, ca.c_str(), nullptr, cert.empty() ? nullptr : cert.c_str(),
                               key.empty() ? nullptr : key.c_str(), noPassphrase);
    if (rc == MOSQ_ERR_SUCCESS)
        rc = mosquitto_tls_opts_set(mosq_, 1 /* SSL_VERIFY_PEER */, nullptr, nullptr);
    if (rc == MOSQ_ERR_SUCCESS) rc = mosquitto_tls_insecure_set(mosq_, false); // host name too
    if (rc != MOSQ_ERR_SUCCESS) return refuse(std::string("TLS set-up: ") + mosquitto_strerror(rc));
    if (!config_.username.empty()) {
        rc = mosquitto_username_pw_set(mosq_, config_.username.c_str(),
                                       password.empty() ? nullptr : password.c_str());
        std::fill(password.begin(), password.end(), '\0'); // libmosquitto keeps its own copy
        if (rc != MOSQ_ERR_SUCCESS) return refuse(mosquitto_strerror(rc));
    }
    mosquitto_connect_callback_set(mosq_, onConnect);
    mosquitto_disconnect_callback_set(mosq_, onDisconnect);
    mosquitto_message_callback_set(mosq_, onMessage);
    mosquitto_publish_callback_set(mosq_, onPublish);
    mosquitto_log_callback_set(mosq_, onLog);
    withNode([&] { node_.prepareSession(); }); // the will, before the first CONNECT
    started_ = true;
    stopping_ = false;
    thread_ = std::thread([this] { run(); });
    return true;
}

void MosquittoLink::stop() {
    if (!started_.exchange(false)) return;
    // NDEATH first, while the network thread still runs to write it (QoS 1: wait for the
    // PUBACK, briefly: a dead broker must not hold the shutdown up).
    withNode([&] { node_.shutdown(); });
    {
        std::unique_lock lock(wait_mutex_);
        wake_.wait_for(lock, std::chrono::seconds(2),
                       [&] { return death_sent_ || death_mid_ < 0; });
    }
    stopping_ = true;
    mosquitto_disconnect(mosq_);
    wake_.notify_all();
    if (thread_.joinable()) thread_.join();
    setStatus(LinkState::Stopped, "shop-floor link stopped");
}

bool MosquittoLink::publish(const std::string& topic, const std::string& bytes, int qos,
                            bool retain) {
    int mid = 0;
    const int rc = mosquitto_publish(mosq_, &mid, topic.c_str(), static_cast<int>(bytes.size()),
                                     bytes.data(), qos, retain);
    if (rc == MOSQ_ERR_SUCCESS && topic.find("/NDEATH/") != std::string::npos) {
        std::lock_guard lock(wait_mutex_);
        death_mid_ = mid;
        death_sent_ = false;
    }
    return rc == MOSQ_ERR_SUCCESS;
}

bool MosquittoLink::subscribe(const std::string& topic, int qos) {
    return mosquitto_subscribe(mosq_, nullptr, topic.c_str(), qos) == MOSQ_ERR_SUCCESS;
}

void MosquittoLink::setWill(const std::string& topic, const std::string& bytes, int qos,
                            bool retain) {
    mosquitto_will_set(mosq_, topic.c_str(), static_cast<int>(bytes.size()), bytes.data(), qos,
                       retain);
}

void MosquittoLink::onConnect(mosquitto*, void* self, int rc) {
    auto* l = static_cast<MosquittoLink*>(self);
    if (rc != 0) {
        l->setStatus(LinkState::Refused, refusal(rc));
        return;
    }
    l->accepted_ = true;
    l->attempt_ = 0;
    l->setStatus(LinkState::Connected, "connected to " + l->where());
    l->withNode([&] { l->node_.connected(); });
}

void MosquittoLink::onDisconnect(mosquitto*, void* self, int) {
    auto* l = static_cast<MosquittoLink*>(self);
    l->withNode([&] { l->node_.disconnected(); });
    // The status bar says it at once; sessionEnded() adds the reason and the retry.
    if (!l->stopping_ && l->accepted_) // stop() calls this from its own thread
        l->setStatus(LinkState::Reconnecting, "connection to " + l->where() + " lost");
}

void MosquittoLink::onMessage(mosquitto*, void* self, const mosquitto_message* msg) {
    auto* l = static_cast<MosquittoLink*>(self);
    const std::string topic = msg->topic ? msg->topic : "";
    const std::string bytes(static_cast<const char*>(msg->payload),
                            static_cast<std::size_t>(std::max(msg->payloadlen, 0)));
    l->withNode([&] { l->node_.message(topic, bytes); });
}

void MosquittoLink::onPublish(mosquitto*, void* self, int mid) {
    auto* l = static_cast<MosquittoLink*>(self);
    std::lock_guard lock(l->wait_mutex_);
    if (mid == l->death_mid_) {
        l->death_sent_ = true;
        l->wake_.notify_all();
    }
}

void MosquittoLink::onLog(mosquitto*, void* self, int level, const char* text) {
    auto* l = static_cast<MosquittoLink*>(self);
    const std::string line = text ? text : "";
    // libmosquitto reports a failed handshake only here ("OpenSSL Error[0]: error:0A000086:SSL
    // routines::certificate verify failed"); keep the reason for the status bar.
    if (line.find("OpenSSL Error") != std::string::npos) {
        const auto colon = line.rfind(':');
        std::string reason = colon == std::string::npos ? line : line.substr(colon + 1);
        reason.erase(0, reason.find_first_not_of(' '));
        l->tls_error_ = reason;
    }
    if ((level & (MOSQ_LOG_ERR | MOSQ_LOG_WARNING)) && l->options_.log)
        l->options_.log("libmosquitto: " + line);
}

bool MosquittoLink::pause(double seconds) {
    std::unique_lock lock(wait_mutex_);
    return !wake_.wait_for(lock, std::chrono::duration<double>(seconds),
                           [&] { return stopping_.load(); });
}

int socketHungUp(int fd) {
    if (fd < 0) return 0;
    pollfd p{fd, POLLOUT, 0};
    if (::poll(&p, 1, 0) != 1 || (p.revents & (POLLHUP | POLLERR)) == 0) return 0;
    int error = 0;
    socklen_t len = sizeof error;
    if (::getsockopt(fd, SOL_SOCKET, SO_ERROR, &error, &len) != 0 || error == 0) error = ECONNRESET;
    return error;
}

void MosquittoLink::sessionEnded(int rc, int err) {
    withNode([&] { node_.disconnected(); }); // after on_disconnect this changes nothing
    if (stopping_) return;
    const double delay =
        std::min(options_.reconnect_max_s,
                 options_.reconnect_min_s * std::pow(2.0, std::max(attempt_ - 1, 0)));
    char retry[64];
    std::snprintf(retry, sizeof retry, "; retrying in %.3g s", delay);
    const LinkStatus now = status();
    if (!tls_error_.empty())
        setStatus(LinkState::TlsError, "TLS: " + tls_error_ + " (" + where() + ")" + retry);
    else if (now.state == LinkState::Refused && !accepted_)
        setStatus(LinkState::Refused, now.text.substr(0, now.text.find(';')) + retry);
    else
        setStatus(LinkState::Reconnecting,
                  (accepted_ ? "connection to " : "cannot connect to ") + where() + ": " +
                      (rc == MOSQ_ERR_ERRNO ? std::strerror(err) : mosquitto_strerror(rc)) + retry);
    pause(delay);
}

void MosquittoLink::run() {
    // Our own loop instead of mosquitto_loop_start(): libmosquitto's thread gives up for good
    // on a TLS error (an untrusted certificate today may be fixed on the broker tomorrow), and
    // this loop also counts the attempts for the status bar and sets each session's will
    // (the node's bdSeq) before its CONNECT.
    while (!stopping_) {
        ++attempt_;
        accepted_ = false;
        tls_error_.clear();
        setStatus(LinkState::Connecting,
                  "connecting to " + where() + " (attempt " + std::to_string(attempt_) + ")");
        const auto began = std::chrono::steady_clock::now();
        errno = 0;
        int rc =
            mosquitto_connect_async(mosq_, config_.host.c_str(), config_.port, config_.keepalive_s);
        const int connect_errno = errno; // EINPROGRESS/EAGAIN, or why the connect failed
        int err = connect_errno;
        while (rc == MOSQ_ERR_SUCCESS && !stopping_) {
            rc = mosquitto_loop(mosq_, 100, 1); // also sends the keep-alive pings
            err = errno;
            withNode([&] { node_.poll(); }); // what the axis rate held back
            if (rc != MOSQ_ERR_SUCCESS || accepted_) continue;
            // Still no CONNACK. Under TLS libmosquitto 2.0.11 takes a refused TCP connect for a
            // handshake under way: mosquitto_loop() returns at once, again and again, until 1.5
            // keep-alives have passed (45 s by default: a busy loop, and a broker back after an
            // outage reached that much later). A hung-up socket says it at once; an attempt
            // without an answer ends after kConnectTimeoutS.
            if (const int gone = socketHungUp(mosquitto_socket(mosq_))) {
                rc = MOSQ_ERR_ERRNO;
                // libmosquitto may have taken the socket's error already; a connect refused at
                // once left it in errno.
                err = gone == ECONNRESET && connect_errno == ECONNREFUSED ? ECONNREFUSED : gone;
            } else if (std::chrono::steady_clock::now() - began >
                       std::chrono::duration<double>(kConnectTimeoutS)) {
                rc = MOSQ_ERR_ERRNO;
                err = ETIMEDOUT;
            }
        }
        if (stopping_) break;
        if (rc == MOSQ_ERR_TLS && tls_error_.empty()) tls_error_ = "handshake failed";
        mosquitto_disconnect(mosq_); // close whatever is left of the socket
        sessionEnded(rc, err);
    }
    // Let the DISCONNECT out.
    for (int i = 0; i < 10 && mosquitto_loop(mosq_, 50, 1) == MOSQ_ERR_SUCCESS; ++i) {
    }
}

} // namespace cutcell::shopfloor
