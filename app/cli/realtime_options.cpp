#include "realtime_options.h"

#include <charconv>
#include <cstdio>
#include <thread>

namespace cutcell::cli {
namespace {

// Integer value of `name` within [lo, hi]; false (message printed) when it is not one.
bool intOption(const Args& args, const char* name, int lo, int hi, int& value,
               const char* command) {
    const std::string text = option(args, name);
    if (text.empty()) return true;
    int v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size() || v < lo || v > hi) {
        std::fprintf(stderr, "cutcell-cli %s: %s = %s must be an integer in %d .. %d\n", command,
                     name, text.c_str(), lo, hi);
        return false;
    }
    value = v;
    return true;
}

} // namespace

int parseRealtimeOptions(const Args& args, RealtimeSettings& s, const char* command) {
    const int cpus = static_cast<int>(std::thread::hardware_concurrency());
    if (!intOption(args, "--rt-priority", 0, 99, s.priority, command)) return kUsage;
    if (!intOption(args, "--rt-cpu", 0, cpus > 0 ? cpus - 1 : 1023, s.cpu, command)) return kUsage;
    if (flag(args, "--rt-dma-latency")) s.cpu_dma_latency = true;
    if (flag(args, "--no-mlock")) s.lock_memory = false;
    return kOk;
}

} // namespace cutcell::cli
