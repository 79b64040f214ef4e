// The Sparkplug B edge node's session rules (edge_node.h).
#include "devices/shopfloor/edge_node.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace cutcell::shopfloor {

using sparkplug::DataType;
using sparkplug::Metric;
using sparkplug::Value;

const std::vector<MetricInfo> kCellMetrics = {
    {"Machine/Id", 1, DataType::String},
    {"Machine/Name", 2, DataType::String},
    {"Machine/State", 3, DataType::String},
    {"Job/Name", 4, DataType::String},
    {"Job/Progress", 5, DataType::Double},
    {"Job/Pieces Made", 6, DataType::UInt64},
    {"Job/Made", 7, DataType::Text},
    {"Alarms/Active", 8, DataType::Text},
    {"Alarms/Count", 9, DataType::UInt32},
    {"Motion/Override", 10, DataType::Double},
    {"Last Run/Cycle Time", 11, DataType::Double},
    {"Last Run/Tracking RMS", 12, DataType::Double},
    {"Last Run/Tracking Max", 13, DataType::Double},
    {"Last Run/Error Unit", 14, DataType::String},
    {"Last Run/Outcome", 15, DataType::String},
    {"Consumables/Pierces", 16, DataType::UInt64},
    {"Consumables/Arc On", 17, DataType::Double},
    {"Queue/Length", 18, DataType::UInt32},
    {"Link/Queued Messages", 19, DataType::UInt64},
    {"Link/Dropped Messages", 20, DataType::UInt64},
    {"Link/Sessions", 21, DataType::UInt64},
    {kRebirth, 30, DataType::Boolean},
    {kQueueJob, 31, DataType::String},
    {kFeedHold, 32, DataType::Boolean},
    {kClearQueue, 33, DataType::Boolean},
    {kLastCommandResult, 34, DataType::String},
};

namespace {

constexpr const char* kNamespace = "spBv1.0";

std::uint64_t systemMs() {
    using namespace std::chrono;
    return static_cast<std::uint64_t>(
        duration_cast<milliseconds>(system_clock::now().time_since_epoch()).count());
}

std::string joinLines(const std::vector<std::string>& lines) {
    std::string out;
    for (const auto& l : lines)
        out += (out.empty() ? "" : "\n") + l;
    return out;
}

} // namespace

EdgeNode::EdgeNode(EdgeNodeOptions options, SparkplugTransport& transport,
                   ShopfloorCommandSink* commands)
    : options_(std::move(options)), transport_(transport), commands_(commands) {
    if (!options_.clock_ms) options_.clock_ms = systemMs;
    if (!(options_.axis_rate_hz > 0)) options_.axis_rate_hz = 10;
    if (options_.store_forward_capacity == 0) options_.store_forward_capacity = 1;
}

std::string EdgeNode::topic(const std::string& type) const {
    return std::string(kNamespace) + "/" + options_.group_id + "/" + type + "/" +
           options_.edge_node_id;
}

std::uint64_t EdgeNode::now() const {
    return options_.clock_ms();
}

void EdgeNode::note(const std::string& line) {
    if (options_.log) options_.log(line);
}

int EdgeNode::nextSeq() {
    stats_.seq = (stats_.seq + 1) % 256;
    return stats_.seq;
}

std::string EdgeNode::shapeOf(const CellSnapshot& s) const {
    std::string shape = s.machine_id;
    for (std::size_t i = 0; i < std::min(s.axes.size(), kMaxAxes); ++i)
        shape += "|" + s.axes[i].name + "[" + s.axes[i].unit + "]";
    return shape;
}

std::vector<EdgeNode::Slot> EdgeNode::currentMetrics(const CellSnapshot& s) {
    std::vector<Slot> out;
    out.reserve(kCellMetrics.size() + 3 * s.axes.size());
    // A number that is not finite is published as "no value" (is_null): a host can store that,
    // not a NaN. The refusal names the metric (logged once, not at every snapshot).
    auto finite = [&](const std::string& name, double v) -> Value {
        if (std::isfinite(v)) return v;
        const std::string why = "Sparkplug metric '" + name + "': the value is " +
                                (std::isnan(v) ? "NaN" : "Inf") + ", published as null";
        if (why != stats_.last_error) note(why);
        stats_.last_error = why;
        return std::monostate{};
    };
    auto add = [&](std::string name, std::uint64_t alias, DataType type, Value v,
                   std::string unit = {}) -> Slot& {
        Slot& slot = out.emplace_back();
        slot.metric = sparkplug::metric(std::move(name), alias, type, std::move(v));
        if (!unit.empty()) slot.metric.properties.emplace_back("engUnit", std::move(unit));
        return slot;
    };
    // The fixed metrics, in kCellMetrics' order.
    std::size_t next = 0;
    auto fixed = [&](Value v, std::string unit = {}) -> Slot& {
        const MetricInfo& info = kCellMetrics[next++];
        if (const double* d = std::get_if<double>(&v)) v = finite(info.name, *d);
        return add(info.name, info.alias, info.type, std::move(v), std::move(unit));
    };
    const LastRunFigures* r = s.last_run ? &*s.last_run : nullptr;
    const ConsumableCounters* c = s.consumables ? &*s.consumables : nullptr;
    fixed(s.machine_id);
    fixed(s.machine_name);
    fixed(s.state);
    fixed(s.job_name);
    fixed(s.progress).continuous = true; // moves with the axes: at their rate
    fixed(std::uint64_t{s.pieces_made});
    fixed(s.made);
    fixed(joinLines(s.alarms));
    fixed(static_cast<std::uint64_t>(s.alarms.size()));
    fixed(s.override_fraction);
    fixed(r ? Value{r->cycle_time_s} : Value{}, "s");
    fixed(r ? Value{r->tracking_rms} : Value{});
    fixed(r ? Value{r->tracking_max} : Value{});
    fixed(r ? Value{r->error_unit} : Value{});
    fixed(r ? Value{r->outcome} : Value{});
    fixed(c ? Value{std::uint64_t{c->pierces}} : Value{});
    fixed(c ? Value{c->arc_on_s} : Value{}, "s");
    fixed(std::uint64_t{s.queue_length});
    // The link's own counters: reported by the next NBIRTH while offline, not queued.
    fixed(static_cast<std::uint64_t>(queue_.size())).link = true;
    fixed(stats_.dropped).link = true;
    fixed(stats_.sessions).link = true;
    fixed(false); // Node Control/Rebirth
    fixed(std::string());
    fixed(false);
    fixed(false);
    fixed(stats_.last_command_result);
    for (std::size_t i = 0; i < std::min(s.axes.size(), kMaxAxes); ++i) {
        const AxisSnapshot& a = s.axes[i];
        const std::string prefix = "Axes/" + std::to_string(i + 1) + "/";
        const std::uint64_t base = kAxisAliasBase + 10 * i;
        add(prefix + "Name", base, DataType::String, a.name);
        add(prefix + "Position", base + 1, DataType::Double,
            finite(prefix + "Position", a.position), a.unit)
            .continuous = true;
        add(prefix + "Following Error", base + 2, DataType::Double,
            finite(prefix + "Following Error", a.following_error), a.unit)
            .continuous = true;
    }
    return out;
}

std::string EdgeNode::deathPayload() const {
    sparkplug::Payload p;
    p.timestamp_ms = now();
    p.metrics.push_back(
        sparkplug::metric("bdSeq", std::nullopt, DataType::UInt64, std::uint64_t(stats_.bd_seq)));
    return sparkplug::encode(p);
}

void EdgeNode::prepareSession() {
    transport_.setWill(topic("NDEATH"), deathPayload(), 1, false);
}

void EdgeNode::connected() {
    session_ = true;
    stats_.online = true;
    ++stats_.sessions;
    // NCMD first, so that a host answering the NBIRTH with a command finds the subscription.
    transport_.subscribe(topic("NCMD"), 1);
    publishBirth();
    flushQueue();
}

void EdgeNode::disconnected() {
    stats_.online = false;
    if (!session_) return; // no CONNACK: the broker holds no will of ours, the bdSeq stays
    session_ = false;
    // The next session gets the next bdSeq, so a host can tell this session's NDEATH (which the
    // broker may still publish) from the next session's.
    stats_.bd_seq = (stats_.bd_seq + 1) % 256;
    prepareSession();
}

void EdgeNode::shutdown() {
    if (!session_) return;
    transport_.publish(topic("NDEATH"), deathPayload(), 1, false);
    stats_.online = false;
}

void EdgeNode::publishBirth() {
    const CellSnapshot empty;
    const CellSnapshot& s = have_snapshot_ ? last_ : empty;
    std::vector<Slot> slots = currentMetrics(s);
    const std::uint64_t t = now();
    sparkplug::Payload p;
    p.timestamp_ms = t;
    stats_.seq = 0;
    p.seq = 0;
    p.metrics.push_back(
        sparkplug::metric("bdSeq", std::nullopt, DataType::UInt64, std::uint64_t(stats_.bd_seq)));
    for (const Slot& slot : slots) {
        p.metrics.push_back(slot.metric);
        p.metrics.back().timestamp_ms = t;
    }
    published_ = std::move(slots);
    shape_ = shapeOf(s);
    last_axis_ms_ = t;
    ++stats_.births;
    std::string bytes;
    try {
        bytes = sparkplug::encode(p);
    } catch (const sparkplug::PayloadError& e) {
        stats_.last_error = e.what(); // not reached: currentMetrics() cleans every value
        note(e.what());
        return;
    }
    if (!transport_.publish(topic("NBIRTH"), bytes, 0, false)) stats_.online = false;
}

bool EdgeNode::transmit(std::vector<Metric> metrics, std::uint64_t t, bool historical) {
    sparkplug::Payload p;
    p.timestamp_ms = t;
    p.seq = nextSeq();
    for (Metric& m : metrics) {
        m.timestamp_ms = t;
        m.historical = historical;
    }
    p.metrics = std::move(metrics);
    std::string bytes;
    try {
        bytes = sparkplug::encode(p);
    } catch (const sparkplug::PayloadError& e) {
        stats_.last_error = e.what();
        note(e.what());
        return true; // such a message can never be sent: do not keep it
    }
    if (!transport_.publish(topic("NDATA"), bytes, 0, false)) return false;
    ++stats_.data_sent;
    return true;
}

void EdgeNode::sendData(std::vector<Metric> metrics, std::uint64_t t) {
    if (stats_.online) {
        if (transmit(metrics, t, false)) return;
        // The session died under us; its end is reported to disconnected() shortly.
        stats_.online = false;
        note("Sparkplug: NDATA not accepted by the transport; kept for the next session");
    }
    if (queue_.size() >= options_.store_forward_capacity) {
        queue_.pop_front(); // the oldest goes first: the newest state matters most
        ++stats_.dropped;
    }
    queue_.push_back({t, std::move(metrics)});
    stats_.queued = queue_.size();
}

void EdgeNode::flushQueue() {
    while (stats_.online && !queue_.empty()) {
        Pending& next = queue_.front();
        // Keep only metrics the last NBIRTH declared (the machine may have changed meanwhile).
        std::erase_if(next.metrics, [&](const Metric& m) {
            return std::none_of(published_.begin(), published_.end(),
                                [&](const Slot& s) { return s.metric.alias == m.alias; });
        });
        if (!next.metrics.empty() && !transmit(next.metrics, next.timestamp_ms, true)) {
            stats_.online = false; // keep it at the front for the next session
            break;
        }
        queue_.pop_front();
    }
    stats_.queued = queue_.size();
}

void EdgeNode::update(const CellSnapshot& snapshot) {
    last_ = snapshot;
    have_snapshot_ = true;
    if (stats_.online && shapeOf(snapshot) != shape_) {
        publishBirth(); // other metrics than the last NBIRTH declared: a new birth certificate
        return;
    }
    std::vector<Slot> current = currentMetrics(snapshot);
    if (current.size() != published_.size()) {
        published_ = std::move(current); // changed machine while offline: the NBIRTH tells all
        return;
    }
    const std::uint64_t t = now();
    const double interval_ms = 1000.0 / options_.axis_rate_hz;
    const bool continuous_due = static_cast<double>(t - last_axis_ms_) >= interval_ms;
    std::vector<Metric> changed;
    bool continuous_sent = false;
    for (std::size_t i = 0; i < current.size(); ++i) {
        Slot& known = published_[i];
        const Slot& now_ = current[i];
        if (now_.metric.value == known.metric.value) continue;
        if (now_.link && !stats_.online) continue; // the next NBIRTH carries the link's counters
        if (now_.continuous && !continuous_due) continue; // kept for the next period
        known.metric.value = now_.metric.value;
        Metric m = now_.metric;
        m.name.clear(); // by alias: the NBIRTH gave name and alias together
        m.properties.clear();
        changed.push_back(std::move(m));
        continuous_sent = continuous_sent || now_.continuous;
    }
    if (continuous_sent) last_axis_ms_ = t;
    if (!changed.empty()) sendData(std::move(changed), t);
}

void EdgeNode::poll() {
    if (have_snapshot_) update(last_);
}

void EdgeNode::commandResult(bool accepted, const std::string& text) {
    (accepted ? stats_.commands_accepted : stats_.commands_refused)++;
    stats_.last_command_result = text;
    if (!accepted) note("Sparkplug NCMD " + text);
    const MetricInfo& info = kCellMetrics.back();
    for (Slot& s : published_)
        if (s.metric.alias == info.alias) s.metric.value = text;
    // Published even when the text repeats: each command gets its answer.
    sendData({sparkplug::metric({}, info.alias, info.type, text)}, now());
}

void EdgeNode::handleCommand(const Metric& m) {
    std::string name = m.name;
    if (name.empty() && m.alias)
        for (const Slot& s : published_)
            if (s.metric.alias == m.alias) name = s.metric.name;
    const bool* flag = std::get_if<bool>(&m.value);
    const std::string* text = std::get_if<std::string>(&m.value);
    auto needTrue = [&](const char* what) {
        if (flag && *flag) return true;
        commandResult(false, "refused: " + std::string(what) + " takes the Boolean true, got " +
                                 (m.isNull() ? std::string("null") : toString(m.type)));
        return false;
    };
    if (name == kRebirth) {
        if (!needTrue(kRebirth)) return;
        ++stats_.commands_accepted;
        stats_.last_command_result = std::string("accepted: ") + kRebirth;
        publishBirth(); // seq 0 again, the same bdSeq; its Last Command Result says why
        flushQueue();
    } else if (name == kQueueJob) {
        if (!text) {
            commandResult(false, std::string("refused: ") + kQueueJob + " takes a String, got " +
                                     toString(m.type));
        } else if (!commands_) {
            commandResult(false, std::string("refused: ") + kQueueJob +
                                     ": this cell takes no jobs from the network");
        } else {
            const std::string error = commands_->queueJob(*text, options_.command_source);
            if (error.empty())
                commandResult(true, std::string("accepted: ") + kQueueJob + " (" +
                                        std::to_string(text->size()) + " bytes queued)");
            else
                commandResult(false, std::string("refused: ") + kQueueJob + ": " + error);
        }
    } else if (name == kFeedHold || name == kClearQueue) {
        if (!needTrue(name.c_str())) return;
        if (!commands_) {
            commandResult(false, "refused: " + name + ": this cell takes no commands");
            return;
        }
        if (name == kFeedHold)
            commands_->feedHold();
        else
            commands_->clearQueue();
        commandResult(true, "accepted: " + name);
    } else {
        // Start, Reset, an E-STOP release or anything else: never from the network.
        commandResult(false, "refused: " + (name.empty() ? m.label() : "'" + name + "'") +
                                 " is not a command this cell takes from the network (it takes " +
                                 kRebirth + ", " + kQueueJob + ", " + kFeedHold + ", " +
                                 kClearQueue + ")");
    }
}

void EdgeNode::message(const std::string& t, const std::string& bytes) {
    if (t != topic("NCMD")) {
        note("Sparkplug: ignored a message on " + t);
        return;
    }
    std::string error;
    const auto payload = sparkplug::decode(bytes, &error);
    if (!payload) {
        commandResult(false, "refused: NCMD " + error);
        return;
    }
    for (const Metric& m : payload->metrics)
        handleCommand(m);
}

} // namespace cutcell::shopfloor
