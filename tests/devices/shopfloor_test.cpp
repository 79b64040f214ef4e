// The shop-floor link (devices/shopfloor): the Sparkplug B payload codec, the edge node's
// session rules against a fake transport (seq and bdSeq, aliases, rebirth, store and forward,
// commands, axis rate) and the configuration reader's refusals. The link against a real broker
// (ShopfloorBroker.*) is in shopfloor_broker_test.cpp.
#include "core/job/job_io.h"
#include "core/json/json.h"
#include "devices/shopfloor/edge_node.h"
#include "devices/shopfloor/mosquitto_link.h"
#include "devices/shopfloor/shopfloor_config.h"
#include "devices/shopfloor/sparkplug_payload.h"
#include "shopfloor_test_util.h"
#include "tests/support/free_local_port.h"

#include <gtest/gtest.h>
#include <mosquitto.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <mutex>
#include <optional>
#include <poll.h>
#include <pwd.h>
#include <sstream>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

using namespace cutcell::shopfloor;
namespace sp = cutcell::sparkplug;
using namespace cutcell::shopfloor::test;

namespace {

struct Sent {
    std::string topic;
    sp::Payload payload;
    int qos;
    bool retain;
};

class FakeTransport : public SparkplugTransport {
  public:
    bool up = true; // whether publish() is taken
    std::vector<Sent> sent;
    std::vector<std::string> subscriptions;
    Sent will;

    bool publish(const std::string& topic, const std::string& bytes, int qos,
                 bool retain) override {
        if (!up) return false;
        sent.push_back({topic, *sp::decode(bytes), qos, retain});
        return true;
    }
    bool subscribe(const std::string& topic, int) override {
        subscriptions.push_back(topic);
        return true;
    }
    void setWill(const std::string& topic, const std::string& bytes, int qos,
                 bool retain) override {
        will = {topic, *sp::decode(bytes), qos, retain};
    }
    std::vector<Sent> take() { return std::exchange(sent, {}); }
};

struct Node {
    FakeTransport transport;
    FakeCell commands;
    std::uint64_t clock = 1'700'000'000'000;
    EdgeNodeOptions options() {
        EdgeNodeOptions o;
        o.group_id = "shop";
        o.edge_node_id = "cell-1";
        o.clock_ms = [this] { return clock; };
        return o;
    }
    EdgeNode node;
    explicit Node(std::size_t capacity = 100, double axis_hz = 10)
        : node(
              [&] {
                  EdgeNodeOptions o = options();
                  o.store_forward_capacity = capacity;
                  o.axis_rate_hz = axis_hz;
                  return o;
              }(),
              transport, &commands) {}
    void connect() {
        transport.up = true;
        node.prepareSession();
        node.connected();
    }
};

std::string ncmd(const std::vector<sp::Metric>& metrics) {
    sp::Payload p;
    p.timestamp_ms = 1;
    p.metrics = metrics;
    return sp::encode(p);
}

} // namespace

// --- the payload codec ---

TEST(SparkplugPayload, RoundTripsEveryWrittenType) {
    sp::Payload p;
    p.timestamp_ms = 1234;
    p.seq = 7;
    p.metrics = {sp::metric("i8", 1, sp::DataType::Int8, std::int64_t{-5}),
                 sp::metric("i32", 2, sp::DataType::Int32, std::int64_t{-70000}),
                 sp::metric("i64", 3, sp::DataType::Int64, std::int64_t{-1}),
                 sp::metric("u64", 4, sp::DataType::UInt64, std::uint64_t{1} << 60),
                 sp::metric("f", 5, sp::DataType::Float, 1.5f),
                 sp::metric("d", 6, sp::DataType::Double, 2.25),
                 sp::metric("b", 7, sp::DataType::Boolean, true),
                 sp::metric("t", 8, sp::DataType::Text, std::string("a\nb")),
                 sp::metric("n", 9, sp::DataType::Double, std::monostate{})};
    p.metrics[5].properties = {{"engUnit", "mm"}};
    const auto back = sp::decode(sp::encode(p));
    ASSERT_TRUE(back);
    EXPECT_EQ(back->seq, 7u);
    EXPECT_EQ(back->timestamp_ms, 1234u);
    ASSERT_EQ(back->metrics.size(), 9u);
    for (std::size_t i = 0; i < p.metrics.size(); ++i) {
        EXPECT_EQ(back->metrics[i].name, p.metrics[i].name);
        EXPECT_EQ(back->metrics[i].alias, p.metrics[i].alias);
        EXPECT_EQ(back->metrics[i].type, p.metrics[i].type);
        EXPECT_EQ(back->metrics[i].value, p.metrics[i].value) << p.metrics[i].name;
    }
    EXPECT_EQ(back->metrics[5].properties, p.metrics[5].properties);
    EXPECT_TRUE(back->metrics[8].isNull());
}

TEST(SparkplugPayload, RefusesNaNInfAndOutOfRangeNamingTheMetric) {
    auto refusal = [](sp::Metric m) {
        sp::Payload p;
        p.metrics = {std::move(m)};
        try {
            sp::encode(p);
        } catch (const sp::PayloadError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(refusal(sp::metric("Job/Progress", 5, sp::DataType::Double, std::nan(""))),
              "Sparkplug metric 'Job/Progress' (alias 5): the value is NaN (only finite numbers "
              "are published)");
    EXPECT_NE(refusal(sp::metric("x", 1, sp::DataType::Float, HUGE_VAL)).find("Inf"),
              std::string::npos);
    EXPECT_EQ(refusal(sp::metric("small", 2, sp::DataType::UInt8, std::int64_t{256})),
              "Sparkplug metric 'small' (alias 2): 256 is outside the range of UInt8 [0, 255]");
    EXPECT_NE(refusal(sp::metric("flag", 3, sp::DataType::Boolean, 1.0)).find("true or false"),
              std::string::npos);
    EXPECT_NE(refusal(sp::metric("", std::nullopt, sp::DataType::Double, 1.0)).find("name or"),
              std::string::npos);
    std::string error;
    EXPECT_FALSE(sp::decode("\xff\xff\xff", &error));
    EXPECT_NE(error.find("not a Sparkplug B payload"), std::string::npos);
}

// --- the edge node's session rules ---

TEST(EdgeNode, BirthDeclaresEveryMetricWithItsAliasAndTheWillsBdSeq) {
    Node n;
    n.node.update(cell(3));
    n.connect();
    EXPECT_EQ(n.transport.will.topic, "spBv1.0/shop/NDEATH/cell-1");
    EXPECT_EQ(n.transport.will.qos, 1);
    EXPECT_FALSE(n.transport.will.retain);
    EXPECT_EQ(u64(n.transport.will.payload.find("bdSeq")), 0u);
    EXPECT_FALSE(n.transport.will.payload.seq);
    ASSERT_EQ(n.transport.subscriptions, std::vector<std::string>{"spBv1.0/shop/NCMD/cell-1"});
    const auto sent = n.transport.take();
    ASSERT_EQ(sent.size(), 1u);
    EXPECT_EQ(sent[0].topic, "spBv1.0/shop/NBIRTH/cell-1");
    const sp::Payload& birth = sent[0].payload;
    EXPECT_EQ(birth.seq, 0u);
    EXPECT_EQ(u64(birth.find("bdSeq")), 0u);
    for (const MetricInfo& info : kCellMetrics) {
        const sp::Metric* m = birth.find(info.name);
        ASSERT_TRUE(m) << info.name;
        EXPECT_EQ(m->alias, info.alias) << info.name;
        EXPECT_EQ(m->type, info.type) << info.name;
        EXPECT_EQ(m->timestamp_ms, n.clock);
    }
    const sp::Metric* pos = birth.find("Axes/3/Position");
    ASSERT_TRUE(pos);
    EXPECT_EQ(pos->alias, kAxisAliasBase + 21);
    EXPECT_EQ(pos->properties,
              (std::vector<std::pair<std::string, std::string>>{{"engUnit", "deg"}}));
    EXPECT_EQ(std::get<std::string>(birth.find("Axes/2/Name")->value), "J2");
    EXPECT_TRUE(birth.find("Last Run/Cycle Time")->isNull()); // no run yet
    EXPECT_EQ(birth.metrics.size(), 1 + kCellMetrics.size() + 9);
}

TEST(EdgeNode, DataCarriesOnlyTheChangedMetricsByAlias) {
    Node n;
    n.node.update(cell());
    n.connect();
    n.transport.take();
    CellSnapshot s = cell();
    s.state = "Running";
    s.alarms = {"torch: arc lost", "J2 following error"};
    n.node.update(s);
    n.node.update(s); // no change: nothing
    const auto sent = n.transport.take();
    ASSERT_EQ(sent.size(), 1u);
    EXPECT_EQ(sent[0].topic, "spBv1.0/shop/NDATA/cell-1");
    EXPECT_EQ(sent[0].payload.seq, 1u);
    ASSERT_EQ(sent[0].payload.metrics.size(), 3u);
    for (const sp::Metric& m : sent[0].payload.metrics) {
        EXPECT_TRUE(m.name.empty());
        EXPECT_TRUE(m.properties.empty());
        EXPECT_FALSE(m.historical);
    }
    EXPECT_EQ(std::get<std::string>(sent[0].payload.findAlias(3)->value), "Running");
    EXPECT_EQ(std::get<std::string>(sent[0].payload.findAlias(8)->value),
              "torch: arc lost\nJ2 following error");
    EXPECT_EQ(u64(sent[0].payload.findAlias(9)), 2u);
}

TEST(EdgeNode, SeqWrapsFrom255To0AndTheBirthIsZero) {
    Node n;
    CellSnapshot s = cell(0);
    n.node.update(s);
    n.connect();
    for (int i = 1; i <= 300; ++i) {
        s.pieces_made = static_cast<std::uint64_t>(i);
        n.node.update(s);
    }
    const auto sent = n.transport.take();
    ASSERT_EQ(sent.size(), 301u); // NBIRTH, 300 NDATA
    EXPECT_EQ(sent[0].payload.seq, 0u);
    for (std::size_t i = 1; i < sent.size(); ++i)
        EXPECT_EQ(*sent[i].payload.seq, i % 256) << i;
    EXPECT_EQ(sent[255].payload.seq, 255u);
    EXPECT_EQ(sent[256].payload.seq, 0u);
}

TEST(EdgeNode, BdSeqStepsOncePerSessionAndTheWillFollowsIt) {
    Node n;
    n.node.update(cell());
    for (int session = 0; session < 258; ++session) {
        n.connect();
        const auto sent = n.transport.take();
        ASSERT_EQ(u64(sent.at(0).payload.find("bdSeq")), static_cast<std::uint64_t>(session % 256));
        ASSERT_EQ(u64(n.transport.will.payload.find("bdSeq")), session % 256u);
        n.transport.up = false;
        n.node.disconnected();
        ASSERT_EQ(u64(n.transport.will.payload.find("bdSeq")), (session + 1) % 256u);
        n.node.disconnected(); // twice (callback and loop): one step only
        ASSERT_EQ(u64(n.transport.will.payload.find("bdSeq")), (session + 1) % 256u);
    }
}

TEST(EdgeNode, RebirthCommandSendsANewBirthWithSeqZeroAndTheSameBdSeq) {
    Node n;
    n.node.update(cell());
    n.connect();
    n.transport.up = false;
    n.node.disconnected();
    n.connect(); // bdSeq 1
    CellSnapshot s = cell();
    s.progress = 0.5;
    n.clock += 1000; // progress goes at the axis rate
    n.node.update(s);
    n.transport.take();
    n.node.message("spBv1.0/shop/NCMD/cell-1",
                   ncmd({sp::metric(kRebirth, std::nullopt, sp::DataType::Boolean, true)}));
    const auto sent = n.transport.take();
    ASSERT_EQ(sent.size(), 1u);
    EXPECT_EQ(sent[0].topic, "spBv1.0/shop/NBIRTH/cell-1");
    EXPECT_EQ(sent[0].payload.seq, 0u);
    EXPECT_EQ(u64(sent[0].payload.find("bdSeq")), 1u);
    EXPECT_EQ(std::get<double>(sent[0].payload.find("Job/Progress")->value), 0.5);
    EXPECT_EQ(std::get<std::string>(sent[0].payload.find(kLastCommandResult)->value),
              "accepted: Node Control/Rebirth");
    s.progress = 0.6;
    n.clock += 1000;
    n.node.update(s);
    EXPECT_EQ(n.transport.take().at(0).payload.seq, 1u);
}

TEST(EdgeNode, StoreAndForwardIsBoundedCountsDropsAndFlushesInOrder) {
    Node n(5);
    n.node.update(cell());
    n.connect();
    n.transport.up = false;
    n.node.disconnected();
    CellSnapshot s = cell();
    for (int i = 1; i <= 8; ++i) {
        n.clock += 1000;
        s.pieces_made = static_cast<std::uint64_t>(i);
        n.node.update(s);
    }
    EXPECT_EQ(n.node.stats().queued, 5u);
    EXPECT_EQ(n.node.stats().dropped, 3u);
    n.transport.take();
    n.clock += 1000;
    n.connect();
    const auto sent = n.transport.take();
    ASSERT_EQ(sent.size(), 6u);
    const sp::Payload& birth = sent[0].payload;
    EXPECT_EQ(u64(birth.find("bdSeq")), 1u);
    EXPECT_EQ(u64(birth.find("Job/Pieces Made")), 8u);       // the state now
    EXPECT_EQ(u64(birth.find("Link/Dropped Messages")), 3u); // reported
    EXPECT_EQ(u64(birth.find("Link/Queued Messages")), 5u);
    for (std::size_t i = 1; i < sent.size(); ++i) {
        const sp::Payload& p = sent[i].payload;
        EXPECT_EQ(p.seq, i);
        ASSERT_EQ(p.metrics.size(), 1u);
        EXPECT_EQ(u64(&p.metrics[0]), i + 3); // the oldest three went
        EXPECT_TRUE(p.metrics[0].historical);
        EXPECT_EQ(p.timestamp_ms, 1'700'000'000'000u + 1000 * (i + 3)); // when it happened
    }
    EXPECT_EQ(n.node.stats().queued, 0u);
}

TEST(EdgeNode, CommandsAreGuardedAndEachGetsItsAnswer) {
    Node n;
    n.node.update(cell());
    n.connect();
    n.transport.take();
    const std::string topic = "spBv1.0/shop/NCMD/cell-1";
    auto answer = [&] {
        const auto sent = n.transport.take();
        EXPECT_EQ(sent.size(), 1u);
        if (sent.empty()) return std::string();
        const sp::Metric* m = sent.back().payload.findAlias(34);
        return m ? std::get<std::string>(m->value) : std::string("(no result)");
    };
    n.node.message(topic, ncmd({sp::metric(kQueueJob, std::nullopt, sp::DataType::String,
                                           std::string("{\"schema\": 2}"))}));
    EXPECT_EQ(answer(), "accepted: Node Control/Queue Job (13 bytes queued)");
    ASSERT_EQ(n.commands.jobs.size(), 1u);
    EXPECT_EQ(n.commands.jobs[0].second, "shop floor (Sparkplug NCMD)");
    n.node.message(topic, ncmd({sp::metric(kQueueJob, std::nullopt, sp::DataType::String,
                                           std::string("bad job"))}));
    EXPECT_EQ(answer(), "refused: Node Control/Queue Job: machine.pipe.radius_mm = -3 mm is "
                        "outside [1, 500] mm");
    n.node.message(topic, ncmd({sp::metric(kFeedHold, 32, sp::DataType::Boolean, true)}));
    EXPECT_EQ(answer(), "accepted: Node Control/Feed Hold");
    // By alias only, as a host may send it after the NBIRTH.
    n.node.message(topic, ncmd({sp::metric("", 33, sp::DataType::Boolean, true)}));
    EXPECT_EQ(answer(), "accepted: Node Control/Clear Queue");
    EXPECT_EQ(n.commands.holds, 1);
    EXPECT_EQ(n.commands.clears, 1);
    for (const char* never : {"Node Control/Start", "Node Control/Reset",
                              "Node Control/Release E-Stop", kLastCommandResult}) {
        n.node.message(topic, ncmd({sp::metric(never, std::nullopt, sp::DataType::Boolean, true)}));
        const std::string a = answer();
        EXPECT_EQ(
            a.rfind(std::string("refused: '") + never + "' is not a command this cell takes", 0),
            0u)
            << a;
    }
    n.node.message(topic,
                   ncmd({sp::metric(kFeedHold, 32, sp::DataType::String, std::string("1"))}));
    EXPECT_EQ(answer(), "refused: Node Control/Feed Hold takes the Boolean true, got String");
    n.node.message(topic, "\xff\xfe garbage");
    EXPECT_NE(answer().find("refused: NCMD not a Sparkplug B payload"), std::string::npos);
    EXPECT_EQ(n.commands.holds, 1); // nothing else reached the cell
    EXPECT_EQ(n.commands.jobs.size(), 1u);
    EXPECT_EQ(n.node.stats().commands_accepted, 3u);
    EXPECT_EQ(n.node.stats().commands_refused, 7u);
}

TEST(EdgeNode, AxisDataIsRateLimitedOtherMetricsAreNot) {
    Node n(100, 10); // 10 Hz: one axis message per 100 ms at most
    n.node.update(cell(6));
    n.connect();
    n.transport.take();
    CellSnapshot s = cell(6);
    int axis_messages = 0, state_messages = 0;
    for (int ms = 1; ms <= 2000; ++ms) { // 2 s at 1 kHz of snapshots
        n.clock += 1;
        for (auto& a : s.axes)
            a.position = std::sin(ms * 0.001) * 10;
        if (ms == 555) s.state = "Paused"; // between two axis periods: goes at once
        n.node.update(s);
        for (const Sent& m : n.transport.take()) {
            const bool axis = m.payload.findAlias(kAxisAliasBase + 1) != nullptr;
            axis_messages += axis;
            if (m.payload.findAlias(3)) {
                ++state_messages;
                EXPECT_EQ(ms, 555);
                EXPECT_FALSE(axis);
            }
        }
    }
    EXPECT_EQ(state_messages, 1);
    EXPECT_GE(axis_messages, 19);
    EXPECT_LE(axis_messages, 20);
    // The last position is not kept back when the snapshots stop: poll() sends it when due.
    s.axes[0].position = 41;
    n.clock += 100;
    n.node.update(s); // due: goes now
    n.transport.take();
    s.axes[0].position = 42;
    n.clock += 1;
    n.node.update(s);
    EXPECT_TRUE(n.transport.take().empty());
    n.clock += 99;
    n.node.poll();
    const auto sent = n.transport.take();
    ASSERT_EQ(sent.size(), 1u);
    EXPECT_EQ(std::get<double>(sent[0].payload.findAlias(kAxisAliasBase + 1)->value), 42.0);
}

TEST(EdgeNode, ANaNIsPublishedAsNullAndNamed) {
    Node n;
    std::vector<std::string> log;
    n.node.update(cell());
    n.connect();
    n.transport.take();
    CellSnapshot s = cell();
    s.progress = std::nan("");
    n.clock += 1000;
    n.node.update(s);
    const auto sent = n.transport.take();
    ASSERT_EQ(sent.size(), 1u);
    EXPECT_TRUE(sent[0].payload.findAlias(5)->isNull());
    EXPECT_EQ(n.node.stats().last_error,
              "Sparkplug metric 'Job/Progress': the value is NaN, published as null");
}

TEST(EdgeNode, AMachineWithOtherAxesIsBornAgain) {
    Node n;
    n.node.update(cell(2));
    n.connect();
    n.transport.take();
    n.node.update(cell(4));
    const auto sent = n.transport.take();
    ASSERT_EQ(sent.size(), 1u);
    EXPECT_EQ(sent[0].topic, "spBv1.0/shop/NBIRTH/cell-1");
    EXPECT_TRUE(sent[0].payload.find("Axes/4/Following Error"));
}

TEST(EdgeNode, CostPerSnapshotIsSmall) {
    // The benchmark: a 6-axis cell handed over at 60 Hz, axes changing every time, published at
    // 10 Hz (the fake transport decodes too, so this overstates the node's own cost).
    Node n(100, 10);
    n.node.update(cell(6));
    n.connect();
    CellSnapshot s = cell(6);
    const int snapshots = 6000; // 100 s of a 60 Hz GUI timer
    const std::clock_t c0 = std::clock();
    for (int i = 0; i < snapshots; ++i) {
        n.clock += 16;
        for (auto& a : s.axes)
            a.position = i * 0.01;
        s.progress = i / double(snapshots);
        n.node.update(s);
        if (n.transport.sent.size() > 1000) n.transport.sent.clear();
    }
    const double cpu_s = double(std::clock() - c0) / CLOCKS_PER_SEC;
    const double share = cpu_s / (snapshots * 0.016);
    std::printf("[ bench    ] edge node: %.1f us per snapshot, %.3f %% of one core at 60 Hz "
                "snapshots / 10 Hz axis data, %llu NDATA\n",
                1e6 * cpu_s / snapshots, 100 * share,
                static_cast<unsigned long long>(n.node.stats().data_sent));
    EXPECT_LT(share, 0.02);
    // Throughput: every snapshot due, 6 axis positions changed: one 6-metric NDATA each.
    const std::uint64_t before = n.node.stats().data_sent;
    const std::clock_t c1 = std::clock();
    for (int i = 0; i < snapshots; ++i) {
        n.clock += 100;
        for (auto& a : s.axes)
            a.position = 1000 + i * 0.01;
        n.node.update(s);
        if (n.transport.sent.size() > 1000) n.transport.sent.clear();
    }
    const double cpu2 = double(std::clock() - c1) / CLOCKS_PER_SEC;
    const auto sent = n.node.stats().data_sent - before;
    EXPECT_EQ(sent, static_cast<std::uint64_t>(snapshots));
    std::printf("[ bench    ] edge node: %.0f NDATA/s of 6 changed metrics on one core (encode "
                "and hand over; the fake transport's decoding included)\n",
                static_cast<double>(sent) / cpu2);
}

// --- the configuration file ---

namespace {

std::string refusal(const std::string& text) {
    try {
        parseShopfloorConfig(text);
    } catch (const ShopfloorConfigError& e) {
        return e.what();
    }
    return "accepted";
}

} // namespace

TEST(ShopfloorConfig, ReadsAndWritesTheSameSettings) {
    const ShopfloorConfig c = parseShopfloorConfig(configText(R"(, "axis_rate_hz": 2.5)"));
    EXPECT_TRUE(c.enabled);
    EXPECT_EQ(c.host, "broker.shop.lan");
    EXPECT_EQ(c.port, 8883);
    EXPECT_EQ(c.edge_node_id, "cell-07");
    EXPECT_EQ(c.axis_rate_hz, 2.5);
    EXPECT_EQ(c.store_forward_capacity, 10000);
    EXPECT_EQ(c.keepalive_s, 30);
    const ShopfloorConfig back = parseShopfloorConfig(writeShopfloorConfig(c));
    EXPECT_EQ(writeShopfloorConfig(back), writeShopfloorConfig(c));
    // Off unless configured.
    EXPECT_FALSE(parseShopfloorConfig(R"({"format": "cutcell-shopfloor", "version": 1})").enabled);
}

TEST(ShopfloorConfig, RefusesNamingKeyValueUnitAndLimit) {
    const std::string p = "shop-floor configuration: ";
    EXPECT_EQ(refusal(configText(R"(, "hots": "x")")),
              p + "unknown key \"hots\" (did you mean host?); the keys are format, version, "
                  "enabled, host, port, group_id, edge_node_id, username, password_file, tls, "
                  "axis_rate_hz, store_forward_capacity, keepalive_s");
    EXPECT_EQ(refusal(configText(R"(, "port": 70000)")).find("port") == std::string::npos, false);
    EXPECT_EQ(refusal(R"({"format": "cutcell-shopfloor", "version": 1, "port": 70000})"),
              p + "port = 70000 is outside [1, 65535]");
    EXPECT_EQ(refusal(R"({"format": "cutcell-shopfloor", "version": 1, "axis_rate_hz": 20})"),
              p + "axis_rate_hz = 20 Hz is outside [0.1, 10] Hz");
    EXPECT_EQ(
        refusal(R"({"format": "cutcell-shopfloor", "version": 1, "store_forward_capacity": 0})"),
        p + "store_forward_capacity = 0 messages is outside [1, 100000] messages");
    EXPECT_EQ(refusal(R"({"format": "cutcell-shopfloor", "version": 1, "keepalive_s": 2.5})"),
              p + "keepalive_s = 2.5 s is outside [5, 3600] s");
    EXPECT_EQ(refusal(R"({"format": "cutcell-shopfloor", "version": 1, "keepalive_s": 7.5})"),
              p + "keepalive_s = 7.5 s is not a whole number");
    std::string bad = configText();
    bad.replace(bad.find("cell-07\", \"user"), 7, "cell/07");
    EXPECT_EQ(refusal(bad), p + "edge_node_id = \"cell/07\" contains '/' (Sparkplug ids must not "
                                "contain '+', '#' or '/': they are MQTT topic wildcards and the "
                                "level separator)");
    bad = configText();
    bad.replace(bad.find("cutting"), 7, "cut+ng");
    EXPECT_NE(refusal(bad).find("group_id = \"cut+ng\" contains '+'"), std::string::npos);
    EXPECT_EQ(refusal(R"({"format": "cutcell-shopfloor", "version": 1, "enabled": true,
                          "host": "b", "group_id": "g", "edge_node_id": "e"})"),
              p + "tls.ca_file is missing: the link only talks TLS, and checks the broker's "
                  "certificate against this CA");
    EXPECT_EQ(refusal(configText(R"(, "tls": {"ca_file": "a", "cert_file": "c"})")),
              p + "duplicate key \"tls\" (each key may appear once in an object)");
    EXPECT_EQ(refusal(R"({"format": "cutcell-shopfloor", "version": 1,
                          "tls": {"ca_file": "a", "cert_file": "c"}})"),
              p + "tls.cert_file and tls.key_file go together: give both (a client certificate) "
                  "or neither");
    EXPECT_EQ(refusal(R"({"format": "cutcell-shopfloor", "version": 1, "tls": {"ca_fle": "a"}})"),
              p + "unknown key \"tls.ca_fle\" (did you mean tls.ca_file?); the keys are ca_file, "
                  "cert_file, key_file");
    EXPECT_EQ(refusal(R"({"schema": 2, "name": "a job"})"),
              p + "format = \"\" must be \"cutcell-shopfloor\" (is this a shop-floor "
                  "configuration file?)");
    EXPECT_EQ(refusal(R"({"format": "cutcell-shopfloor", "version": 2})"),
              p + "version = 2 is not one this CutCell reads (1)");
}

TEST(ShopfloorConfig, PasswordFileMustBePrivateAndIsSavedAtomically) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("shopfloor_cfg_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string pw = (dir / "pw").string();
    std::ofstream(pw) << "s3cret\r\nsecond line\n";
    ::chmod(pw.c_str(), 0644);
    try {
        readPasswordFile(pw);
        ADD_FAILURE() << "a world-readable password file was read";
    } catch (const ShopfloorConfigError& e) {
        EXPECT_NE(std::string(e.what()).find("mode 0644): chmod 600 it"), std::string::npos)
            << e.what();
    }
    ::chmod(pw.c_str(), 0600);
    EXPECT_EQ(readPasswordFile(pw), "s3cret");

    ShopfloorConfig c = parseShopfloorConfig(configText());
    const std::string path = (dir / "shopfloor.json").string();
    saveShopfloorConfig(c, path);
    const ShopfloorConfig back = loadShopfloorConfig(path);
    EXPECT_EQ(back.resolve(back.tls.ca_file), (dir / "ca.crt").string());
    EXPECT_EQ(back.resolve("/etc/ca.crt"), "/etc/ca.crt");
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 2); // no temporary
    std::filesystem::remove_all(dir);
}
