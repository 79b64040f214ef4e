#pragma once
// What the shop-floor tests share: a command sink that records, a cell's snapshot, a metric's
// UInt64, a configuration file's text.
#include "core/shopfloor/cell_snapshot.h"
#include "core/shopfloor/shopfloor_command_sink.h"
#include "devices/shopfloor/sparkplug_payload.h"

#include <cstdint>
#include <string>
#include <utility>
#include <variant>
#include <vector>

// Whether this build runs under a sanitizer (timing figures are then printed, not checked).
// GCC says __SANITIZE_ADDRESS__, clang __has_feature(address_sanitizer) / (thread_sanitizer).
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define CUTCELL_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define CUTCELL_SANITIZED 1
#endif
#endif
#ifndef CUTCELL_SANITIZED
#define CUTCELL_SANITIZED 0
#endif

namespace cutcell::shopfloor::test {

namespace sp = cutcell::sparkplug;

class FakeCell : public ShopfloorCommandSink {
  public:
    std::vector<std::pair<std::string, std::string>> jobs;
    int holds = 0, clears = 0;
    std::string queueJob(const std::string& text, const std::string& source) override {
        if (text.find("bad") != std::string::npos)
            return "machine.pipe.radius_mm = -3 mm is outside [1, 500] mm";
        jobs.emplace_back(text, source);
        return {};
    }
    void feedHold() override { ++holds; }
    void clearQueue() override { ++clears; }
};

inline CellSnapshot cell(std::size_t axes = 2) {
    CellSnapshot s;
    s.machine_id = "pipe_robot";
    s.machine_name = "Pipe-cutting robot";
    s.state = "Ready";
    s.job_name = "saddle";
    for (std::size_t i = 0; i < axes; ++i)
        s.axes.push_back({"J" + std::to_string(i + 1), "deg", 0, 0});
    return s;
}

inline std::uint64_t u64(const sp::Metric* m) {
    return m ? std::get<std::uint64_t>(m->value) : 999999;
}

inline std::string configText(const std::string& extra = {}) {
    return R"({"format": "cutcell-shopfloor", "version": 1, "enabled": true,
               "host": "broker.shop.lan", "port": 8883, "group_id": "cutting",
               "edge_node_id": "cell-07", "username": "cell-07",
               "password_file": "broker.password",
               "tls": {"ca_file": "ca.crt"})" +
           extra + "}";
}

} // namespace cutcell::shopfloor::test
