#include "core/process/consumable_counters.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cutcell {
namespace {

struct Used {
    std::int64_t used, life; // life > 0
};

// Per mille, rounded down: a display never rounds 89.96 % up to a "90.0 %" that is not yet a
// warning.
std::int64_t permille(const Used& u) {
    return u.used * 1000 / u.life;
}

std::string percentText(const Used& u) {
    const std::int64_t p = permille(u);
    return std::to_string(p / 10) + (p % 10 ? "." + std::to_string(p % 10) : "") + " %";
}

std::string minutes(std::int64_t ms) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", static_cast<double>(ms) / 60000.0);
    return buf;
}

} // namespace

std::string ConsumableSetId::name() const {
    return std::string(toString(process)) + " / " + consumable;
}

ConsumableLife consumableLifeOf(const CutChart& chart) {
    ConsumableLife life;
    if (chart.life_pierces && *chart.life_pierces > 0) life.pierces = *chart.life_pierces;
    if (chart.life_arc_minutes && *chart.life_arc_minutes > 0)
        life.arc_s = *chart.life_arc_minutes * 60.0;
    return life;
}

const char* toString(WearLevel level) {
    switch (level) {
    case WearLevel::Ok:
        return "ok";
    case WearLevel::Warning:
        return "warning";
    case WearLevel::Alarm:
        return "alarm";
    }
    return "ok";
}

ConsumableWear consumableWear(const ConsumableCounters& c, const ConsumableLife& life) {
    ConsumableWear w;
    w.text = "expected life unknown";
    // Both limits as integers (arc-on time in ms, as counted): the thresholds compare exactly.
    // A life beyond 10^12 s is no life (and would overflow the conversion).
    const std::int64_t lifeArcMs =
        life.arc_s > 0 && life.arc_s < 1e12 ? std::llround(life.arc_s * 1000.0) : 0;
    const Used pierces{c.pierces, life.pierces}, arc{c.arc_on_ms, lifeArcMs};
    const auto consider = [&](const Used& u, WearLimit limit, std::string text) {
        if (u.life <= 0) return;
        // The level is the worse of the two, each decided on integers; the text names the limit
        // with the larger fraction (a tie names pierces).
        const WearLevel level = u.used * 100 >= u.life * kWearAlarmPercent     ? WearLevel::Alarm
                                : u.used * 100 >= u.life * kWearWarningPercent ? WearLevel::Warning
                                                                               : WearLevel::Ok;
        w.level = std::max(w.level, level);
        const double f = static_cast<double>(u.used) / static_cast<double>(u.life);
        if (w.limit != WearLimit::None && f <= w.fraction) return;
        w.fraction = f;
        w.limit = limit;
        w.text = std::move(text) + " (" + percentText(u) + ")";
    };
    consider(pierces, WearLimit::Pierces,
             "pierces: " + std::to_string(c.pierces) + " of " + std::to_string(life.pierces));
    consider(arc, WearLimit::ArcTime,
             "arc-on time: " + minutes(c.arc_on_ms) + " of " + minutes(lifeArcMs) + " min");
    return w;
}

} // namespace cutcell
