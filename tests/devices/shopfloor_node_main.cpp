// A cell's edge node in a process of its own, for the shop-floor tests that kill it (the will
// on kill -9) and measure its CPU: reads a shop-floor configuration, connects, and publishes a
// simulated cell (6 axes moving, progress rising) until it is killed. Jobs queued by NCMD are
// validated with the core's job reader, as a file opened by hand.
//   shopfloor_node_main --config FILE [--period-ms 16]
// Prints "status: <link status>" whenever the link's status changes (stdout, line-buffered).
#include "core/job/job_io.h"
#include "devices/shopfloor/mosquitto_link.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <string>
#include <thread>

using namespace cutcell::shopfloor;

namespace {

// Commands arrive on the link's thread; the main loop reads the counters.
class TestCell : public ShopfloorCommandSink {
  public:
    std::string queueJob(const std::string& text, const std::string& source) override {
        try {
            const cutcell::Job job = cutcell::parseJob(text);
            std::printf("queued job from %s\n", source.c_str());
            ++queued;
            return {};
        } catch (const std::exception& e) { // JobError, or anything the reader lets out
            return e.what();
        }
    }
    void feedHold() override { held = true; }
    void clearQueue() override { queued = 0; }

    std::atomic<unsigned> queued{0};
    std::atomic<bool> held{false};
};

} // namespace

int main(int argc, char** argv) {
    std::setvbuf(stdout, nullptr, _IOLBF, 0);
    std::string config_path;
    int period_ms = 16;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--config") && i + 1 < argc)
            config_path = argv[++i];
        else if (!std::strcmp(argv[i], "--period-ms") && i + 1 < argc)
            period_ms = std::max(1, std::atoi(argv[++i]));
        else {
            std::fprintf(stderr, "usage: %s --config FILE [--period-ms N]\n", argv[0]);
            return 64;
        }
    }
    ShopfloorConfig config;
    try {
        config = loadShopfloorConfig(config_path);
    } catch (const ShopfloorConfigError& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 2;
    }
    TestCell cell;
    MosquittoLinkOptions options;
    options.reconnect_min_s = 0.2;
    options.reconnect_max_s = 2;
    options.log = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };
    MosquittoLink link(config, &cell, options);

    CellSnapshot s;
    s.machine_id = "pipe_robot";
    s.machine_name = "Pipe-cutting robot";
    s.state = "Running";
    s.job_name = "saddle 114x60";
    s.consumables = ConsumableCounters{};
    for (int a = 0; a < 6; ++a)
        s.axes.push_back({"J" + std::to_string(a + 1), a == 5 ? "deg" : "deg", 0, 0});
    link.submit(s); // the first NBIRTH has the real metrics
    std::string error;
    if (!link.start(&error)) {
        std::fprintf(stderr, "cannot start: %s\n", error.c_str());
        return 1;
    }
    const auto t0 = std::chrono::steady_clock::now();
    std::string shown;
    for (;;) {
        const double t =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        for (std::size_t a = 0; a < s.axes.size(); ++a) {
            s.axes[a].position = 30 * std::sin(0.5 * t + static_cast<double>(a));
            s.axes[a].following_error = 0.01 * std::cos(3 * t + static_cast<double>(a));
        }
        s.progress = std::fmod(t / 60.0, 1.0);
        s.pieces_made = static_cast<std::uint64_t>(t / 5);
        s.consumables->pierces = s.pieces_made;
        s.queue_length = cell.queued;
        s.state = cell.held ? "Paused" : "Running";
        link.submit(s);
        const LinkStatus st = link.status();
        if (st.text != shown) std::printf("status: %s\n", (shown = st.text).c_str());
        std::this_thread::sleep_for(std::chrono::milliseconds(period_ms));
    }
}
