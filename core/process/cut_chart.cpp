// The cut-chart library: the figures' table, reading and writing the file, the checks and the
// row lookup (cut_chart.h).
#include "core/process/cut_chart.h"

#include "core/common/c_format.h"
#include "core/job/job_io.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

namespace cutcell {
namespace {

constexpr std::array<CutFigureInfo, kCutFigureCount> kFigures{{
    {"thickness_mm", "mm", 0.1, 300.0, false},
    {"kerf_mm", "mm", 0.05, 10.0, false},
    {"cut_speed_mm_min", "mm/min", 0.0, 100000.0, true},
    {"pierce_height_mm", "mm", 0.0, 50.0, false},
    {"pierce_delay_s", "s", 0.0, 60.0, false},
    {"cut_height_mm", "mm", 0.0, 50.0, false},
    {"arc_voltage_v", "V", 30.0, 400.0, false},
    {"preheat_s", "s", 0.0, 600.0, false},
}};

// The consumable set's figures: whole pierces, arc-on minutes, plasma's slope in V/mm.
constexpr int kLifePiercesMax = 1000000;
constexpr double kLifeMinutesMax = 100000.0;
constexpr double kVoltsPerMmLo = 0.1, kVoltsPerMmHi = 50.0;
constexpr std::size_t kNameMax = 64, kSourceMax = 4000;

const char* const kTopKeys[] = {"format", "version", "note", "charts"};
const char* const kChartKeys[] = {
    "process",      "material",         "consumable",   "source",  "typical_values",
    "life_pierces", "life_arc_minutes", "volts_per_mm", "columns", "rows"};

std::string num(double v) {
    if (std::isnan(v)) return "NaN";
    if (std::isinf(v)) return v > 0 ? "Inf" : "-Inf";
    return formatC("%.6g", v);
}

template <std::size_t N> std::string keyList(const char* const (&keys)[N]) {
    std::string out;
    for (const char* k : keys)
        out += (out.empty() ? "" : ", ") + std::string(k);
    return out;
}

std::string join(const std::vector<std::string>& names) {
    std::string out;
    for (const auto& n : names)
        out += (out.empty() ? "" : ", ") + n;
    return out;
}

// "[0.05, 10] mm", "(0, 100000] mm/min"
std::string rangeText(double lo, double hi, bool loOpen, const char* unit) {
    return (loOpen ? "(" : "[") + num(lo) + ", " + num(hi) + "] " + unit;
}

bool inRange(double v, double lo, double hi, bool loOpen) {
    return std::isfinite(v) && (loOpen ? v > lo : v >= lo) && v <= hi;
}

// "cut chart 'plasma / mild_steel / 45A' (charts[2])"
std::string chartLabel(const CutChart& c, std::size_t i) {
    return "cut chart '" + c.name() + "' (charts[" + std::to_string(i) + "])";
}

[[noreturn]] void fail(const std::string& msg) {
    throw CutChartError(msg);
}

void refuseUnknownKeys(const json::Value& obj, const std::string& where, const char* const* keys,
                       std::size_t count, const std::string& list) {
    for (const auto& kv : obj.asObject()) {
        const std::string& k = kv.first;
        if (std::find_if(keys, keys + count, [&](const char* a) { return k == a; }) == keys + count)
            fail(where + ": unknown key " + json::quote(k) + " (the keys are " + list + ")");
    }
}

const json::Value& member(const json::Value& obj, const char* key, const std::string& where) {
    const json::Value* m = obj.find(key);
    if (!m) fail(where + ": missing key " + std::string(key));
    return *m;
}

std::string stringMember(const json::Value& obj, const char* key, const std::string& where) {
    const json::Value& m = member(obj, key, where);
    if (!m.isString()) fail(where + ": " + key + " must be a string, found " + m.typeName());
    return m.asString();
}

std::optional<double> numberMember(const json::Value& obj, const char* key,
                                   const std::string& where) {
    const json::Value* m = obj.find(key);
    if (!m) return std::nullopt;
    if (!m->isNumber()) fail(where + ": " + key + " must be a number, found " + m->typeName());
    return m->asNumber();
}

bool validMaterial(const std::string& s) {
    if (s.empty() || s.size() > kNameMax || !(s[0] >= 'a' && s[0] <= 'z')) return false;
    return std::all_of(s.begin(), s.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
    });
}

bool validConsumable(const std::string& s) {
    if (s.empty() || s.size() > kNameMax || s.front() == ' ' || s.back() == ' ') return false;
    return std::none_of(s.begin(), s.end(),
                        [](char c) { return static_cast<unsigned char>(c) < 0x20; });
}

CutChart readChart(const json::Value& v, std::size_t i) {
    std::string where = "charts[" + std::to_string(i) + "]";
    if (!v.isObject()) fail(where + " must be an object (a chart), found " + v.typeName());
    CutChart c;
    const std::string processName = stringMember(v, "process", where);
    const auto process = cutProcessFromString(processName);
    if (!process)
        fail(where + ": process = " + json::quote(processName) +
             " is not one of \"plasma\", \"oxy_fuel\", \"laser\"");
    c.process = *process;
    c.material = stringMember(v, "material", where);
    c.consumable = stringMember(v, "consumable", where);
    where = chartLabel(c, i);
    refuseUnknownKeys(v, where, kChartKeys, std::size(kChartKeys), keyList(kChartKeys));
    c.source = stringMember(v, "source", where);
    const json::Value& typical = member(v, "typical_values", where);
    if (!typical.isBool())
        fail(where + ": typical_values must be true or false, found " + typical.typeName());
    c.typical_values = typical.asBool();
    if (const auto p = numberMember(v, "life_pierces", where)) {
        // Range first, then the conversion (1e300 does not fit an int).
        if (!(*p >= 1 && *p <= kLifePiercesMax) || *p != std::floor(*p))
            fail(where + ": life_pierces = " + num(*p) + " pierces is not a whole number in [1, " +
                 std::to_string(kLifePiercesMax) + "]");
        c.life_pierces = static_cast<int>(*p);
    }
    c.life_arc_minutes = numberMember(v, "life_arc_minutes", where);
    c.volts_per_mm = numberMember(v, "volts_per_mm", where);

    const json::Value& cols = member(v, "columns", where);
    if (!cols.isArray())
        fail(where + ": columns must be an array of figure names, found " + cols.typeName());
    for (std::size_t k = 0; k < cols.asArray().size(); ++k) {
        const json::Value& col = cols.asArray()[k];
        const std::string ck = where + ": columns[" + std::to_string(k) + "]";
        const auto f = col.isString() ? cutFigureFromKey(col.asString()) : std::nullopt;
        if (!f) {
            std::string all;
            for (const auto& info : kFigures)
                all += (all.empty() ? "" : ", ") + std::string(info.key);
            fail(ck + " = " + (col.isString() ? json::quote(col.asString()) : col.typeName()) +
                 " is not a figure (one of " + all + ")");
        }
        c.columns.push_back(*f);
    }
    const json::Value& rows = member(v, "rows", where);
    if (!rows.isArray()) fail(where + ": rows must be an array of rows, found " + rows.typeName());
    for (std::size_t r = 0; r < rows.asArray().size(); ++r) {
        const json::Value& row = rows.asArray()[r];
        const std::string rk = where + ": rows[" + std::to_string(r) + "]";
        if (!row.isArray() || row.asArray().size() != c.columns.size())
            fail(rk + " must be an array of " + std::to_string(c.columns.size()) +
                 " numbers, one per column" +
                 (row.isArray() ? "; it has " + std::to_string(row.asArray().size())
                                : ", found " + row.typeName()));
        CutRow out;
        for (std::size_t k = 0; k < c.columns.size(); ++k) {
            const json::Value& cell = row.asArray()[k];
            if (!cell.isNumber())
                fail(rk + ": " + cutFigureInfo(c.columns[k]).key + " must be a number, found " +
                     cell.typeName());
            out.set(c.columns[k], cell.asNumber());
        }
        c.rows.push_back(out);
    }
    return c;
}

void checkChart(const CutChart& c, std::size_t i) {
    const std::string where = chartLabel(c, i);
    if (!validMaterial(c.material))
        fail("charts[" + std::to_string(i) + "]: material = " + json::quote(c.material) +
             " must be 1 to " + std::to_string(kNameMax) +
             " characters a-z, 0-9 and '_', starting with a letter (\"mild_steel\")");
    if (!validConsumable(c.consumable))
        fail("charts[" + std::to_string(i) + "]: consumable = " + json::quote(c.consumable) +
             " must be 1 to " + std::to_string(kNameMax) +
             " characters without control characters or spaces at either end");
    const bool blankSource = std::all_of(c.source.begin(), c.source.end(),
                                         [](char ch) { return ch == ' ' || ch == '\t'; });
    if (blankSource || c.source.size() > kSourceMax)
        fail(where + ": source must say where the figures come from (1 to " +
             std::to_string(kSourceMax) + " characters)");
    if (c.life_pierces && !(*c.life_pierces >= 1 && *c.life_pierces <= kLifePiercesMax))
        fail(where + ": life_pierces = " + std::to_string(*c.life_pierces) +
             " pierces is outside [1, " + std::to_string(kLifePiercesMax) + "]");
    if (c.life_arc_minutes && !inRange(*c.life_arc_minutes, 0.0, kLifeMinutesMax, true))
        fail(where + ": life_arc_minutes = " + num(*c.life_arc_minutes) + " min is outside " +
             rangeText(0.0, kLifeMinutesMax, true, "min"));
    if (c.volts_per_mm) {
        if (c.process != CutProcess::Plasma)
            fail(where +
                 ": volts_per_mm (the arc voltage's slope) is a figure of plasma charts "
                 "only; this chart is " +
                 std::string(toString(c.process)));
        if (!inRange(*c.volts_per_mm, kVoltsPerMmLo, kVoltsPerMmHi, false))
            fail(where + ": volts_per_mm = " + num(*c.volts_per_mm) + " V/mm is outside " +
                 rangeText(kVoltsPerMmLo, kVoltsPerMmHi, false, "V/mm"));
    }

    // Columns: known figures, each once, thickness and cut speed present, the process's own.
    std::array<bool, kCutFigureCount> has{};
    for (const CutFigure f : c.columns) {
        const auto& info = cutFigureInfo(f);
        if (has[static_cast<std::size_t>(f)])
            fail(where + ": column " + info.key + " appears twice");
        has[static_cast<std::size_t>(f)] = true;
        if (!cutFigureApplies(f, c.process))
            fail(where + ": " + info.key + " is a figure of " +
                 (f == CutFigure::ArcVoltageV ? "plasma" : "oxy_fuel") +
                 " charts only; this chart is " + toString(c.process));
    }
    for (const CutFigure f : {CutFigure::ThicknessMm, CutFigure::CutSpeedMmMin})
        if (!has[static_cast<std::size_t>(f)])
            fail(where + ": columns must include " + cutFigureInfo(f).key);
    if (c.rows.empty()) fail(where + ": rows is empty (a chart needs at least one row)");

    for (std::size_t r = 0; r < c.rows.size(); ++r) {
        const CutRow& row = c.rows[r];
        const std::string rk = where + " rows[" + std::to_string(r) + "]";
        for (std::size_t k = 0; k < kCutFigureCount; ++k) {
            const auto f = static_cast<CutFigure>(k);
            const auto& info = cutFigureInfo(f);
            const std::optional<double> v = row.get(f);
            if (v.has_value() != has[k])
                fail(rk + ": " + info.key +
                     (has[k] ? " is missing (it is a column of the chart)"
                             : " is given but is not a column of the chart"));
            if (v && !inRange(*v, info.lo, info.hi, info.loOpen))
                fail(rk + ": " + info.key + " = " + num(*v) + " " + info.unit + " is outside " +
                     rangeText(info.lo, info.hi, info.loOpen, info.unit));
        }
        if (r > 0 && !(row.thicknessMm() > c.rows[r - 1].thicknessMm()))
            fail(rk + ": thickness_mm = " + num(row.thicknessMm()) + " mm is not above rows[" +
                 std::to_string(r - 1) + "]'s " + num(c.rows[r - 1].thicknessMm()) +
                 " mm (rows must be in strictly increasing thickness)");
    }
}

std::string readFile(const std::string& path) {
    try {
        return readTextFile(path); // a folder or a missing file: JobFileError; too big: JobError
    } catch (const JobFileError& e) {
        throw CutChartFileError(std::string("cut charts: ") + e.what());
    } catch (const JobError& e) {
        fail(e.what());
    }
}

} // namespace

const char* toString(CutProcess p) {
    switch (p) {
    case CutProcess::Plasma:
        return "plasma";
    case CutProcess::OxyFuel:
        return "oxy_fuel";
    case CutProcess::Laser:
        return "laser";
    }
    return "?";
}

std::optional<CutProcess> cutProcessFromString(std::string_view s) {
    for (const auto p : {CutProcess::Plasma, CutProcess::OxyFuel, CutProcess::Laser})
        if (s == toString(p)) return p;
    return std::nullopt;
}

const CutFigureInfo& cutFigureInfo(CutFigure f) {
    return kFigures[static_cast<std::size_t>(f)];
}

std::optional<CutFigure> cutFigureFromKey(std::string_view key) {
    for (std::size_t k = 0; k < kCutFigureCount; ++k)
        if (key == kFigures[k].key) return static_cast<CutFigure>(k);
    return std::nullopt;
}

bool cutFigureApplies(CutFigure f, CutProcess p) {
    if (f == CutFigure::ArcVoltageV) return p == CutProcess::Plasma;
    if (f == CutFigure::PreheatS) return p == CutProcess::OxyFuel;
    return true;
}

std::string CutChart::name() const {
    return std::string(toString(process)) + " / " + material + " / " + consumable;
}

const CutChart* CutChartSet::find(CutProcess p, const std::string& material,
                                  const std::string& consumable) const {
    for (const CutChart& c : charts)
        if (c.process == p && c.material == material && c.consumable == consumable) return &c;
    return nullptr;
}

std::vector<std::string> CutChartSet::materials(CutProcess p) const {
    std::vector<std::string> out;
    for (const CutChart& c : charts)
        if (c.process == p && std::find(out.begin(), out.end(), c.material) == out.end())
            out.push_back(c.material);
    return out;
}

std::vector<std::string> CutChartSet::consumables(CutProcess p, const std::string& material) const {
    std::vector<std::string> out;
    for (const CutChart& c : charts)
        if (c.process == p && c.material == material) out.push_back(c.consumable);
    return out;
}

void checkCutCharts(const CutChartSet& set) {
    if (set.version != kCutChartVersion)
        fail("cut charts: version = " + std::to_string(set.version) +
             " is not supported; this CutCell reads version " + std::to_string(kCutChartVersion));
    for (std::size_t i = 0; i < set.charts.size(); ++i) {
        checkChart(set.charts[i], i);
        for (std::size_t j = 0; j < i; ++j) {
            const CutChart &a = set.charts[j], &b = set.charts[i];
            if (a.process == b.process && a.material == b.material && a.consumable == b.consumable)
                fail(chartLabel(b, i) + " repeats charts[" + std::to_string(j) +
                     "] (process, material and consumable together name one chart)");
        }
    }
}

CutChartSet readCutCharts(const json::Value& doc) {
    if (!doc.isObject())
        fail("cut charts: the document must be an object, found " + doc.typeName());
    refuseUnknownKeys(doc, "cut charts", kTopKeys, std::size(kTopKeys), keyList(kTopKeys));
    const std::string format = stringMember(doc, "format", "cut charts");
    if (format != kCutChartFormat)
        fail("cut charts: format = " + json::quote(format) + " is not " +
             json::quote(kCutChartFormat));
    const json::Value& version = member(doc, "version", "cut charts");
    if (!version.isNumber() || version.asNumber() != kCutChartVersion)
        fail("cut charts: version = " +
             (version.isNumber() ? num(version.asNumber()) : version.typeName()) +
             " is not supported; this CutCell reads version " + std::to_string(kCutChartVersion));
    CutChartSet set;
    if (doc.find("note")) set.note = stringMember(doc, "note", "cut charts");
    const json::Value& charts = member(doc, "charts", "cut charts");
    if (!charts.isArray())
        fail("cut charts: charts must be an array of charts, found " + charts.typeName());
    for (std::size_t i = 0; i < charts.asArray().size(); ++i)
        set.charts.push_back(readChart(charts.asArray()[i], i));
    checkCutCharts(set);
    return set;
}

CutChartSet parseCutCharts(const std::string& text) {
    json::Value doc;
    try {
        doc = json::parse(text);
    } catch (const json::ParseError& e) {
        fail(std::string("cut charts: ") + e.what());
    }
    return readCutCharts(doc);
}

CutChartSet loadCutChartsFile(const std::string& path) {
    const std::string text = readFile(path);
    try {
        return parseCutCharts(text);
    } catch (const CutChartError& e) {
        fail(path + ": " + e.what());
    }
}

json::Value cutChartsJson(const CutChartSet& set) {
    checkCutCharts(set);
    json::Array charts;
    for (const CutChart& c : set.charts) {
        json::Object o{{"process", toString(c.process)},
                       {"material", c.material},
                       {"consumable", c.consumable},
                       {"source", c.source},
                       {"typical_values", c.typical_values}};
        if (c.life_pierces) o.emplace_back("life_pierces", *c.life_pierces);
        if (c.life_arc_minutes) o.emplace_back("life_arc_minutes", *c.life_arc_minutes);
        if (c.volts_per_mm) o.emplace_back("volts_per_mm", *c.volts_per_mm);
        json::Array cols, rows;
        for (const CutFigure f : c.columns)
            cols.emplace_back(cutFigureInfo(f).key);
        for (const CutRow& r : c.rows) {
            json::Array cells;
            for (const CutFigure f : c.columns)
                cells.emplace_back(*r.get(f));
            rows.emplace_back(std::move(cells));
        }
        o.emplace_back("columns", std::move(cols));
        o.emplace_back("rows", std::move(rows));
        charts.emplace_back(std::move(o));
    }
    json::Object doc{{"format", kCutChartFormat}, {"version", set.version}};
    if (!set.note.empty()) doc.emplace_back("note", set.note);
    doc.emplace_back("charts", std::move(charts));
    return doc;
}

std::string writeCutCharts(const CutChartSet& set) {
    return json::write(cutChartsJson(set), 2);
}

CutPick pickCutRow(const CutChart& chart, double t) {
    CutPick out;
    out.chart = &chart;
    const std::string key = "process.thickness_mm";
    if (!std::isfinite(t)) {
        out.outcome = Outcome::refuse("the thickness " + num(t) + " mm is not a number", key);
        return out;
    }
    if (chart.rows.empty()) {
        out.outcome = Outcome::refuse("the chart '" + chart.name() + "' has no rows", key);
        return out;
    }
    const double lo = chart.rows.front().thicknessMm(), hi = chart.rows.back().thicknessMm();
    if (t < lo || t > hi) {
        out.outcome = Outcome::refuse(num(t) + " mm is outside the chart '" + chart.name() +
                                          "': " + num(lo) + " .. " + num(hi) + " mm",
                                      key);
        return out;
    }
    const auto above =
        std::lower_bound(chart.rows.begin(), chart.rows.end(), t,
                         [](const CutRow& r, double x) { return r.thicknessMm() < x; });
    if (above->thicknessMm() == t) {
        out.row = *above; // exact at a row
        return out;
    }
    const CutRow& b = *above;
    const CutRow& a = *(above - 1);
    const double w = (t - a.thicknessMm()) / (b.thicknessMm() - a.thicknessMm());
    for (const CutFigure f : chart.columns) {
        const double va = *a.get(f), vb = *b.get(f);
        out.row.set(f, va + w * (vb - va));
    }
    out.row.set(CutFigure::ThicknessMm, t);
    return out;
}

CutPick pickCutRow(const CutChartSet& set, CutProcess p, const std::string& material,
                   const std::string& consumable, double t) {
    CutPick out;
    const std::vector<std::string> materials = set.materials(p);
    if (materials.empty()) {
        std::vector<std::string> have;
        for (const auto q : {CutProcess::Plasma, CutProcess::OxyFuel, CutProcess::Laser})
            if (!set.materials(q).empty()) have.emplace_back(toString(q));
        out.outcome =
            Outcome::refuse(std::string("no cut chart for ") + toString(p) +
                                (have.empty() ? " (the table has no charts)"
                                              : " (the table has charts for " + join(have) + ")"),
                            "process.material");
        return out;
    }
    if (std::find(materials.begin(), materials.end(), material) == materials.end()) {
        out.outcome = Outcome::refuse(std::string("no cut chart for ") + toString(p) + " on " +
                                          json::quote(material) + "; the materials for " +
                                          toString(p) + " are " + join(materials),
                                      "process.material");
        return out;
    }
    const CutChart* chart = set.find(p, material, consumable);
    if (!chart) {
        out.outcome =
            Outcome::refuse(std::string("no cut chart '") + toString(p) + " / " + material + " / " +
                                consumable + "'; the consumable sets for " + toString(p) + " on " +
                                material + " are " + join(set.consumables(p, material)),
                            "process.consumable");
        return out;
    }
    return pickCutRow(*chart, t);
}

const CutChartSet& shippedCutCharts() {
    static const CutChartSet set = parseCutCharts(shippedCutChartsText());
    return set;
}

} // namespace cutcell
