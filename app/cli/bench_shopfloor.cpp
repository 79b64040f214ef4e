// cutcell-cli bench-shopfloor: the shop-floor link's figures against a local Mosquitto broker
// (TLS, password file; devices/shopfloor/local_broker.h) read by a host on libmosquitto that
// decodes every message and checks its seq. Printed, never asserted.
//
// Cells mode (default): N simulated cells - each a MosquittoLink of its own, fed the GUI's way
// (a snapshot every 100 ms: six axes moving, progress, a job ending every 30 s) - for a window
// of S seconds: messages and bytes per second per cell, the latency host-side, seq errors, the
// CPU of the edge nodes (this process without the host's thread) and of the broker, and the
// broker's own $SYS figures.
//
// Outage mode (--outage): the job run in real time on the simulated rig three times - without
// the link, with it, and with the broker killed (SIGKILL) a third into the run and started again
// at two thirds - with the engine's timing figures side by side, and what the host received once
// the broker was back: the stored messages in order, flagged historical, before any live one.
#include "cli_commands.h"
#include "engine_run.h"

#include "core/job/default_job.h"
#include "core/machine/machine_registry.h"
#include "core/shopfloor/telemetry_snapshot.h"
#include "devices/shopfloor/local_broker.h"
#include "devices/shopfloor/mosquitto_link.h"
#include "devices/shopfloor/sparkplug_payload.h"

#include <mosquitto.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <ctime>
#include <map>
#include <memory>
#include <mutex>
#include <pthread.h>
#include <sys/resource.h>
#include <thread>
#include <vector>

namespace cutcell::cli {
namespace {

using Clock = std::chrono::steady_clock;
constexpr const char* kGroup = "bench";

std::uint64_t epochMs() {
    return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::milliseconds>(
                                          std::chrono::system_clock::now().time_since_epoch())
                                          .count());
}

double processCpuS() {
    rusage u{};
    ::getrusage(RUSAGE_SELF, &u);
    return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double threadCpuS(std::thread& t) {
    clockid_t id;
    timespec ts{};
    if (::pthread_getcpuclockid(t.native_handle(), &id) != 0 || ::clock_gettime(id, &ts) != 0)
        return 0;
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// What the host saw of one edge node.
struct NodeTally {
    std::uint64_t births = 0, deaths = 0, data = 0, bytes = 0;
    std::uint64_t seq_errors = 0;   // an NDATA whose seq is not the last one's + 1 (mod 256)
    std::uint64_t historical = 0;   // NDATA flagged is_historical (sent from the queue)
    std::uint64_t out_of_order = 0; // historical after a live one, or older than the one before
    int last_seq = -1;
    bool live_since_birth = false;
    std::uint64_t last_historical_ms = 0;
};

// The host application: subscribes to the group's topics and the broker's $SYS, decodes every
// payload and keeps tallies. Its network loop runs on a thread of its own (its CPU is measured
// apart from the edge nodes').
class BenchHost {
  public:
    BenchHost(const shopfloor::LocalBroker& broker, bool persistent) {
        mosquitto_lib_init();
        m_ = mosquitto_new("bench-host", !persistent, this);
        const std::string ca = broker.folder() + "/ca.crt";
        mosquitto_tls_set(m_, ca.c_str(), nullptr, nullptr, nullptr, nullptr);
        mosquitto_username_pw_set(m_, "host", "host-secret");
        mosquitto_reconnect_delay_set(m_, 1, 1, false);
        mosquitto_connect_callback_set(m_, [](mosquitto* m, void* self, int rc) {
            if (rc != 0) return;
            mosquitto_subscribe(m, nullptr, "spBv1.0/bench/#", 1);
            mosquitto_subscribe(m, nullptr, "$SYS/broker/#", 0);
            static_cast<BenchHost*>(self)->connected_ = true;
        });
        mosquitto_disconnect_callback_set(m_, [](mosquitto*, void* self, int) {
            static_cast<BenchHost*>(self)->connected_ = false;
        });
        mosquitto_message_callback_set(m_,
                                       [](mosquitto*, void* self, const mosquitto_message* msg) {
                                           static_cast<BenchHost*>(self)->received(msg);
                                       });
        mosquitto_connect_async(m_, "127.0.0.1", broker.port(), 30);
        // Our own loop: mosquitto_loop_forever() gives up for good on the TLS error a killed
        // broker leaves, and a refused connect under TLS is only seen as a hung-up socket (see
        // MosquittoLink::run).
        thread_ = std::thread([this] {
            while (!stop_) {
                int rc = mosquitto_loop(m_, 100, 1);
                if (rc == MOSQ_ERR_SUCCESS && !connected_ &&
                    shopfloor::socketHungUp(mosquitto_socket(m_)))
                    rc = MOSQ_ERR_CONN_LOST;
                if (rc == MOSQ_ERR_SUCCESS || stop_) continue;
                connected_ = false;
                std::this_thread::sleep_for(std::chrono::milliseconds(500));
                mosquitto_reconnect_async(m_);
            }
        });
    }
    ~BenchHost() {
        stop_ = true;
        if (thread_.joinable()) thread_.join();
        mosquitto_disconnect(m_);
        mosquitto_destroy(m_);
    }
    bool waitConnected(int seconds) {
        const auto until = Clock::now() + std::chrono::seconds(seconds);
        while (!connected_ && Clock::now() < until)
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        return connected_;
    }
    double cpuS() { return threadCpuS(thread_); }

    std::map<std::string, NodeTally> tallies() {
        std::lock_guard lock(mutex_);
        return nodes_;
    }
    std::vector<double> takeLatencies() {
        std::lock_guard lock(mutex_);
        return std::exchange(latency_ms_, {});
    }
    std::string sys(const std::string& key) {
        std::lock_guard lock(mutex_);
        const auto it = sys_.find(key);
        return it == sys_.end() ? std::string() : it->second;
    }

  private:
    void received(const mosquitto_message* msg) {
        const std::string topic = msg->topic;
        const std::string bytes(static_cast<const char*>(msg->payload),
                                static_cast<std::size_t>(msg->payloadlen));
        std::lock_guard lock(mutex_);
        if (topic.rfind("$SYS/", 0) == 0) {
            sys_[topic] = bytes;
            return;
        }
        // spBv1.0/<group>/<type>/<edge>
        const std::size_t a = topic.find('/', 8), b = topic.find('/', a + 1);
        if (a == std::string::npos || b == std::string::npos) return;
        const std::string type = topic.substr(a + 1, b - a - 1), edge = topic.substr(b + 1);
        const auto payload = sparkplug::decode(bytes);
        if (!payload) return;
        NodeTally& n = nodes_[edge];
        n.bytes += bytes.size();
        if (type == "NBIRTH") {
            ++n.births;
            n.last_seq = 0;
            n.live_since_birth = false;
            n.last_historical_ms = 0;
        } else if (type == "NDEATH") {
            ++n.deaths;
        } else if (type == "NDATA") {
            ++n.data;
            const int seq = payload->seq ? static_cast<int>(*payload->seq) : -2;
            if (n.last_seq < 0 || seq != (n.last_seq + 1) % 256) ++n.seq_errors;
            n.last_seq = seq;
            const bool historical = !payload->metrics.empty() && payload->metrics[0].historical;
            if (historical) {
                ++n.historical;
                if (n.live_since_birth || payload->timestamp_ms < n.last_historical_ms)
                    ++n.out_of_order;
                n.last_historical_ms = payload->timestamp_ms;
            } else {
                n.live_since_birth = true;
                latency_ms_.push_back(static_cast<double>(epochMs()) -
                                      static_cast<double>(payload->timestamp_ms));
            }
        }
    }

    mosquitto* m_ = nullptr;
    std::thread thread_;
    std::atomic<bool> connected_{false}, stop_{false};
    std::mutex mutex_;
    std::map<std::string, NodeTally> nodes_;
    std::map<std::string, std::string> sys_;
    std::vector<double> latency_ms_;
};

double percentile(std::vector<double> v, double p) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    return v[static_cast<std::size_t>(std::lround(p * static_cast<double>(v.size() - 1)))];
}

double sysNumber(BenchHost& host, const std::string& key) {
    const std::string s = host.sys(key);
    try {
        return s.empty() ? -1 : std::stod(s);
    } catch (const std::exception&) {
        return -1;
    }
}

// A simulated cell's snapshot at time t: a 6-axis robot running 30 s jobs.
void simulate(shopfloor::CellSnapshot& s, int cell, double t) {
    constexpr double job_s = 30;
    const double phase = 0.37 * cell;
    const double in_job = std::fmod(t + phase * 10, job_s);
    const auto jobs = static_cast<std::uint64_t>((t + phase * 10) / job_s);
    s.state = in_job < 0.2 ? "Completed" : "Running";
    s.progress = in_job / job_s;
    if (jobs != s.pieces_made) {
        s.pieces_made = jobs;
        s.made = std::to_string(jobs) + " pieces";
        s.last_run = shopfloor::LastRunFigures{job_s, 0.012, 0.041, "deg", "completed"};
    }
    for (std::size_t i = 0; i < s.axes.size(); ++i) {
        const double w = 2 * 3.141592653589793 / (8 + static_cast<double>(i));
        s.axes[i].position = 90 * std::sin(w * t + phase);
        s.axes[i].following_error = 0.02 * std::cos(w * t + phase);
    }
}

shopfloor::MosquittoLinkOptions quietLink() {
    shopfloor::MosquittoLinkOptions o;
    o.reconnect_min_s = 0.5;
    o.reconnect_max_s = 2;
    o.log = [](const std::string&) {}; // the bench prints its own figures
    return o;
}

void put(json::Object& out, const char* key, double value) {
    out.emplace_back(key, value);
}

int benchCells(shopfloor::LocalBroker& broker, const BenchShopfloorOptions& o, json::Object& out) {
    const int count = o.cells.value_or(1);
    BenchHost host(broker, false);
    if (!host.waitConnected(20)) {
        std::fprintf(stderr, "bench-shopfloor: the host did not connect to the local broker\n");
        return kFailure;
    }
    std::vector<std::unique_ptr<shopfloor::MosquittoLink>> links;
    std::vector<shopfloor::CellSnapshot> cells(static_cast<std::size_t>(count));
    const auto t0 = Clock::now();
    for (int i = 0; i < count; ++i) {
        char edge[32];
        std::snprintf(edge, sizeof edge, "cell-%03d", i + 1);
        shopfloor::CellSnapshot& s = cells[static_cast<std::size_t>(i)];
        s.machine_id = "pipe_robot";
        s.machine_name = "Pipe-cutting robot";
        s.job_name = "saddle";
        for (int a = 1; a <= 6; ++a)
            s.axes.push_back({"J" + std::to_string(a), "deg", 0, 0});
        simulate(s, i, 0);
        links.push_back(std::make_unique<shopfloor::MosquittoLink>(
            broker.cellConfig(kGroup, edge, "cell"), nullptr, quietLink()));
        links.back()->submit(s);
        std::string error;
        if (!links.back()->start(&error)) {
            std::fprintf(stderr, "bench-shopfloor: cell %s: %s\n", edge, error.c_str());
            return kFailure;
        }
    }
    const auto online = [&] {
        return std::all_of(links.begin(), links.end(),
                           [](const auto& l) { return l->stats().online; });
    };
    while (!online()) {
        if (Clock::now() - t0 > std::chrono::seconds(120)) {
            std::fprintf(stderr, "bench-shopfloor: not every cell came online in 120 s\n");
            return kFailure;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    const double connect_s = std::chrono::duration<double>(Clock::now() - t0).count();

    // The GUI's pace: a snapshot of every cell each 100 ms. Two seconds of warm-up first.
    const auto feed_until = [&](Clock::time_point until) {
        auto next = Clock::now();
        while (next < until) {
            const double t = std::chrono::duration<double>(next - t0).count();
            for (std::size_t i = 0; i < cells.size(); ++i) {
                simulate(cells[i], static_cast<int>(i), t);
                links[i]->submit(cells[i]);
            }
            next += std::chrono::milliseconds(100);
            std::this_thread::sleep_until(next);
        }
    };
    feed_until(Clock::now() + std::chrono::seconds(2));
    host.takeLatencies();
    const auto before = host.tallies();
    const double cpu0 = processCpuS(), host0 = host.cpuS(), broker0 = broker.cpuSeconds();
    const auto w0 = Clock::now();
    feed_until(w0 + std::chrono::milliseconds(static_cast<long>(o.seconds * 1000)));
    const double window = std::chrono::duration<double>(Clock::now() - w0).count();
    const double nodes_cpu = (processCpuS() - cpu0) - (host.cpuS() - host0);
    const double broker_cpu = broker.cpuSeconds() - broker0;
    const auto after = host.tallies();
    const std::vector<double> latency = host.takeLatencies();

    std::uint64_t data = 0, bytes = 0, seq_errors = 0;
    for (const auto& [edge, n] : after) {
        const auto it = before.find(edge);
        const NodeTally zero;
        const NodeTally& b = it == before.end() ? zero : it->second;
        data += n.data - b.data;
        bytes += n.bytes - b.bytes;
        seq_errors += n.seq_errors - b.seq_errors;
    }
    const double per_cell = static_cast<double>(data) / window / count;
    put(out, "shopfloor_cells", count);
    put(out, "shopfloor_window_s", window);
    put(out, "shopfloor_connect_all_s", connect_s);
    put(out, "shopfloor_ndata_per_s_per_cell", per_cell);
    put(out, "shopfloor_messages_per_s_all_cells", static_cast<double>(data) / window);
    put(out, "shopfloor_bytes_per_s_per_cell", static_cast<double>(bytes) / window / count);
    if (!latency.empty()) { // none received: no figure rather than a 0 that reads as "fast"
        put(out, "shopfloor_latency_ms_p50", percentile(latency, 0.5));
        put(out, "shopfloor_latency_ms_p99", percentile(latency, 0.99));
        put(out, "shopfloor_latency_ms_max", percentile(latency, 1.0));
    }
    put(out, "shopfloor_seq_errors", static_cast<double>(seq_errors));
    put(out, "shopfloor_node_cpu_pct_per_cell", 100 * nodes_cpu / window / count);
    put(out, "shopfloor_nodes_cpu_pct_all", 100 * nodes_cpu / window);
    put(out, "shopfloor_host_cpu_pct", 100 * (host.cpuS() - host0) / window);
    put(out, "shopfloor_broker_cpu_pct", 100 * broker_cpu / window);
    put(out, "broker_clients_connected", sysNumber(host, "$SYS/broker/clients/connected"));
    put(out, "broker_msgs_received_per_s_1min",
        sysNumber(host, "$SYS/broker/load/messages/received/1min") / 60);
    put(out, "broker_msgs_sent_per_s_1min",
        sysNumber(host, "$SYS/broker/load/messages/sent/1min") / 60);
    put(out, "broker_bytes_received_per_s_1min",
        sysNumber(host, "$SYS/broker/load/bytes/received/1min") / 60);
    std::uint64_t dropped = 0;
    for (const auto& l : links) {
        dropped += l->stats().dropped;
        l->stop();
    }
    put(out, "shopfloor_dropped", static_cast<double>(dropped));
    return kOk;
}

// The engine's timing figures of one variant over the rounds: median, min and max of each.
void putCycles(json::Object& out, const std::string& variant, const std::vector<CycleStats>& runs) {
    const auto put3 = [&](const char* what, auto field) {
        std::vector<double> v;
        for (const CycleStats& c : runs)
            v.push_back(static_cast<double>(field(c)));
        const std::string key = "engine_" + variant + "_" + what;
        out.emplace_back(key, percentile(v, 0.5));
        if (runs.size() > 1) {
            out.emplace_back(key + "_min", percentile(v, 0));
            out.emplace_back(key + "_max", percentile(v, 1));
        }
    };
    put3("jitter_us_p50", [](const CycleStats& c) { return c.jitter_us_p50; });
    put3("jitter_us_p99", [](const CycleStats& c) { return c.jitter_us_p99; });
    put3("jitter_us_max", [](const CycleStats& c) { return c.jitter_us_max; });
    put3("work_us_max", [](const CycleStats& c) { return c.work_us_max; });
    put3("overruns", [](const CycleStats& c) { return c.overruns; });
    put3("missed_deadlines", [](const CycleStats& c) { return c.missed_deadlines; });
    put3("telemetry_dropped", [](const CycleStats& c) { return c.telemetry_dropped; });
}

// What one run with the link left at the host.
struct OutageTally {
    std::uint64_t stored = 0, dropped = 0, historical = 0, out_of_order = 0, seq_errors = 0;
    std::uint64_t sessions = 0;
    bool restarted = true;
};

// Kills and restarts the broker on a thread of its own that lives as long as the benchmark: the
// broker's death signal follows the thread that started it (local_broker.h), so a restart made
// by a short-lived thread would end with that thread.
class BrokerKeeper {
  public:
    explicit BrokerKeeper(shopfloor::LocalBroker& broker)
        : broker_(broker), thread_([this] { serve(); }) {}
    ~BrokerKeeper() {
        ask(Quit);
        thread_.join();
    }
    void kill() { ask(Kill); }
    bool restart() { return ask(Restart); }

  private:
    enum Request { None, Kill, Restart, Quit };
    bool ask(Request r) {
        std::unique_lock lock(mutex_);
        request_ = r;
        wake_.notify_all();
        wake_.wait(lock, [this] { return request_ == None || request_ == Quit; });
        return ok_;
    }
    void serve() {
        std::unique_lock lock(mutex_);
        for (;;) {
            wake_.wait(lock, [this] { return request_ != None; });
            if (request_ == Quit) return;
            if (request_ == Kill) broker_.stop(false);
            if (request_ == Restart) ok_ = broker_.restart();
            request_ = None;
            wake_.notify_all();
        }
    }
    shopfloor::LocalBroker& broker_;
    std::mutex mutex_;
    std::condition_variable wake_;
    Request request_ = None;
    bool ok_ = true;
    std::thread thread_;
};

// One run of the job with a link of its own (edge node `edge`); with `outage_s` > 0 the broker is
// killed that long into the run and started again as long after.
EngineRunResult linkedRun(const Job& job, const MachineModule& module, const MachinePlan& plan,
                          shopfloor::LocalBroker& broker, BrokerKeeper& keeper, BenchHost& host,
                          const std::string& edge, double outage_s, OutageTally& tally) {
    shopfloor::MosquittoLinkOptions options = quietLink();
    options.log = [](const std::string& line) { // a few lines: the link's sessions
        std::fprintf(stderr, "bench-shopfloor: link: %s\n", line.c_str());
    };
    shopfloor::MosquittoLink link(broker.cellConfig(kGroup, edge, "cell"), nullptr, options);
    shopfloor::CellSnapshot snap = shopfloor::cellSnapshotOf(job, module);
    link.submit(snap);
    std::string error;
    if (!link.start(&error)) {
        std::fprintf(stderr, "bench-shopfloor: %s\n", error.c_str());
        return {};
    }
    EngineRunSetup setup;
    setup.command = "bench-shopfloor";
    setup.realtime = true;
    setup.quiet = true;
    auto last = Clock::now();
    setup.on_telemetry = [&](MotionEngine&, const TelemetrySample& t) {
        shopfloor::applyTelemetry(snap, t);
        if (Clock::now() - last < std::chrono::milliseconds(50)) return;
        last = Clock::now();
        link.submit(snap);
        tally.stored = std::max(tally.stored, link.stats().queued);
    };
    std::atomic<bool> restarted{outage_s <= 0};
    std::thread outage([&] {
        if (outage_s <= 0) return;
        std::this_thread::sleep_for(std::chrono::duration<double>(outage_s));
        keeper.kill();
        std::this_thread::sleep_for(std::chrono::duration<double>(outage_s));
        restarted = keeper.restart();
    });
    struct JoinAtEnd {
        std::thread& thread;
        ~JoinAtEnd() { thread.join(); }
    } join_at_end{outage};
    const EngineRunResult run = runOnEngine(job, module, plan, setup);
    for (int i = 0; i < 1200 && !restarted; ++i) // the run may end before the broker is back
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    // What the host has once the node sent its queue.
    snap.state = "Completed";
    link.submit(snap);
    const auto until = Clock::now() + std::chrono::seconds(30);
    while (Clock::now() < until && !(link.stats().online && link.stats().queued == 0 &&
                                     host.tallies()[edge].historical >= tally.stored))
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    const NodeTally n = host.tallies()[edge];
    tally.dropped = link.stats().dropped;
    tally.sessions = link.stats().sessions;
    tally.historical = n.historical;
    tally.out_of_order = n.out_of_order;
    tally.seq_errors = n.seq_errors;
    tally.restarted = restarted;
    link.stop();
    return run;
}

int benchOutage(shopfloor::LocalBroker& broker, const BenchShopfloorOptions& o, json::Object& out) {
    Job job;
    int code = kOk;
    if (o.job.empty())
        job = defaultJob();
    else if (!loadJobArg(o.job, job, &code))
        return code;
    job.engine.runs_dir.clear(); // no run logs from a benchmark
    const MachineModule& module = machineFor(job);
    const MachinePlan plan = module.plan(job, {});
    if (!plan.ok()) {
        std::fprintf(stderr, "bench-shopfloor: %s\n", plan.outcome.message.c_str());
        return kUnreachable;
    }
    BenchHost host(broker, true); // persistent: the broker keeps what arrives while it is away
    if (!host.waitConnected(20)) {
        std::fprintf(stderr, "bench-shopfloor: the host did not connect to the local broker\n");
        return kFailure;
    }
    BrokerKeeper keeper(broker);
    // Rounds of three runs - without the link, with it, with the broker lost - interleaved so
    // that the machine's changing load falls on all three alike.
    std::vector<CycleStats> alone, linked, lost;
    std::vector<OutageTally> outages;
    const int rounds = o.rounds.value_or(1);
    for (int r = 1; r <= rounds; ++r) {
        EngineRunSetup setup;
        setup.command = "bench-shopfloor";
        setup.realtime = true;
        setup.quiet = true;
        const EngineRunResult a = runOnEngine(job, module, plan, setup);
        if (a.code != kOk) return a.code;
        alone.push_back(a.cycles);
        OutageTally ignored, tally;
        const std::string round = std::to_string(r);
        const EngineRunResult b =
            linkedRun(job, module, plan, broker, keeper, host, "cell-link-" + round, 0, ignored);
        if (b.code != kOk) return b.code;
        linked.push_back(b.cycles);
        const EngineRunResult c = linkedRun(job, module, plan, broker, keeper, host,
                                            "cell-outage-" + round, a.wall_s / 3, tally);
        if (c.code != kOk) return c.code;
        lost.push_back(c.cycles);
        outages.push_back(tally);
        put(out, ("outage_" + round + "_s").c_str(), a.wall_s / 3);
    }
    putCycles(out, "without_link", alone);
    putCycles(out, "with_link", linked);
    putCycles(out, "broker_lost", lost);
    for (std::size_t i = 0; i < outages.size(); ++i) {
        const OutageTally& t = outages[i];
        const std::string k = "outage_" + std::to_string(i + 1) + "_";
        out.emplace_back(k + "broker_restarted", t.restarted ? 1.0 : 0.0);
        out.emplace_back(k + "messages_stored", static_cast<double>(t.stored));
        out.emplace_back(k + "messages_dropped", static_cast<double>(t.dropped));
        out.emplace_back(k + "historical_received", static_cast<double>(t.historical));
        out.emplace_back(k + "historical_out_of_order", static_cast<double>(t.out_of_order));
        out.emplace_back(k + "seq_errors", static_cast<double>(t.seq_errors));
        out.emplace_back(k + "sessions", static_cast<double>(t.sessions));
    }
    return kOk;
}

} // namespace

int runBenchShopfloor(const BenchShopfloorOptions& o) {
    shopfloor::LocalBroker broker;
    const std::string why = broker.start({{"cell", "cell-secret"}, {"host", "host-secret"}}, 1);
    if (!why.empty()) {
        std::fprintf(stderr, "bench-shopfloor: no local broker: %s\n", why.c_str());
        return kFailure;
    }
    json::Object out;
    const int code = o.outage ? benchOutage(broker, o, out) : benchCells(broker, o, out);
    const json::Value doc(std::move(out));
    if (o.json)
        std::fputs((json::write(doc) + "\n").c_str(), stdout);
    else
        for (const auto& [k, v] : doc.asObject())
            std::printf("%-40s %.6g\n", k.c_str(), v.asNumber());
    return code;
}

} // namespace cutcell::cli
