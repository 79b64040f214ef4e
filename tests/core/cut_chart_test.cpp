// The cut-chart library (core/process/cut_chart.h): the shipped table loads, says where its
// figures come from and writes back byte for byte; a row is picked exactly at a row and linearly
// between rows (a property on random thicknesses); a thickness outside a chart is refused with
// the chart's range; the reader refuses unknown keys, values out of range, NaN, thicknesses that
// do not increase and repeated charts, naming the field; writing and parsing round-trip.
#include "core/process/cut_chart.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>

namespace cutcell {
namespace {

const std::string kShipped = std::string(CUTCELL_SOURCE_DIR) + "/resources/process/cut_charts.json";

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// The message of the CutChartError that parsing `text` throws ("" when it does not throw).
std::string parseError(const std::string& text) {
    try {
        parseCutCharts(text);
    } catch (const CutChartError& e) {
        return e.what();
    }
    return "";
}

std::string checkError(const CutChartSet& set) {
    try {
        checkCutCharts(set);
    } catch (const CutChartError& e) {
        return e.what();
    }
    return "";
}

// A small valid document; `chart` replaces the one chart's body, `extraTop` adds top keys.
std::string doc(const std::string& chart, const std::string& extraTop = "") {
    return R"({"format": "cutcell-cut-charts", "version": 1, )" + extraTop + R"("charts": [)" +
           chart + "]}";
}
const std::string kPlasma =
    R"({"process": "plasma", "material": "mild_steel", "consumable": "45A", "source": "test",
        "typical_values": true,
        "columns": ["thickness_mm", "cut_speed_mm_min", "kerf_mm", "arc_voltage_v"],
        "rows": [[1, 8000, 1.2, 110], [3, 4000, 1.5, 120], [6, 1500, 1.9, 130]]})";

// A set with every kind of figure, built in code as the GUI's editor would.
CutChartSet fullSet() {
    CutChartSet set;
    set.note = "unit test";
    CutChart p;
    p.process = CutProcess::Plasma;
    p.material = "mild_steel";
    p.consumable = "85A shielded";
    p.source = "test figures";
    p.life_pierces = 700;
    p.life_arc_minutes = 1.0 / 3.0;
    p.volts_per_mm = 0.1 + 0.2;
    p.columns = {CutFigure::ThicknessMm,    CutFigure::CutSpeedMmMin, CutFigure::KerfMm,
                 CutFigure::PierceHeightMm, CutFigure::PierceDelayS,  CutFigure::CutHeightMm,
                 CutFigure::ArcVoltageV};
    for (int i = 0; i < 4; ++i) {
        CutRow r;
        const double t = 2.0 + 3.3 * i;
        r.set(CutFigure::ThicknessMm, t);
        r.set(CutFigure::CutSpeedMmMin, 9000.0 / (1.0 + t));
        r.set(CutFigure::KerfMm, 1.1 + 0.07 * t);
        r.set(CutFigure::PierceHeightMm, 3.8);
        r.set(CutFigure::PierceDelayS, 0.1 * i);
        r.set(CutFigure::CutHeightMm, 1.5);
        r.set(CutFigure::ArcVoltageV, 115.0 + 1.7 * t);
        p.rows.push_back(r);
    }
    CutChart o;
    o.process = CutProcess::OxyFuel;
    o.material = "mild_steel";
    o.consumable = "tip 1";
    o.source = "test figures";
    o.typical_values = false;
    o.columns = {CutFigure::ThicknessMm, CutFigure::PreheatS, CutFigure::CutSpeedMmMin};
    for (const double t : {6.0, 12.0, 25.0}) {
        CutRow r;
        r.set(CutFigure::ThicknessMm, t);
        r.set(CutFigure::PreheatS, 2.0 + t);
        r.set(CutFigure::CutSpeedMmMin, 800.0 - 10.0 * t);
        o.rows.push_back(r);
    }
    CutChart l;
    l.process = CutProcess::Laser;
    l.material = "mild_steel";
    l.consumable = "3 kW O2";
    l.source = "test figures";
    l.columns = {CutFigure::ThicknessMm, CutFigure::CutSpeedMmMin};
    for (const double t : {1.0, 5.0}) {
        CutRow r;
        r.set(CutFigure::ThicknessMm, t);
        r.set(CutFigure::CutSpeedMmMin, 10000.0 / t);
        l.rows.push_back(r);
    }
    set.charts = {p, o, l};
    return set;
}

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

TEST(CutChart, ProcessNamesRoundTrip) {
    for (const auto p : {CutProcess::Plasma, CutProcess::OxyFuel, CutProcess::Laser})
        EXPECT_EQ(cutProcessFromString(toString(p)), p);
    EXPECT_EQ(toString(CutProcess::OxyFuel), std::string("oxy_fuel"));
    EXPECT_FALSE(cutProcessFromString("Plasma").has_value());
    EXPECT_FALSE(cutProcessFromString("").has_value());
}

TEST(CutChart, ShippedTableLoadsAndEveryChartSaysWhereItsFiguresComeFrom) {
    const CutChartSet set = loadCutChartsFile(kShipped);
    ASSERT_GE(set.charts.size(), 4u);
    for (const CutChart& c : set.charts) {
        EXPECT_GE(c.source.size(), 40u) << c.name();
        EXPECT_TRUE(c.typical_values) << c.name();
        EXPECT_TRUE(has(c.source, "ypical values")) << c.name() << ": " << c.source;
        EXPECT_GE(c.rows.size(), 2u) << c.name();
    }
    // At least two consumable sets for plasma on mild steel, and plasma on stainless.
    EXPECT_GE(set.consumables(CutProcess::Plasma, "mild_steel").size(), 2u);
    EXPECT_FALSE(set.consumables(CutProcess::Plasma, "stainless_steel").empty());
}

TEST(CutChart, ShippedTableWritesBackByteForByte) {
    const std::string text = readText(kShipped);
    ASSERT_FALSE(text.empty());
    EXPECT_EQ(writeCutCharts(parseCutCharts(text)), text);
}

TEST(CutChart, TheCompiledInTableIsTheFile) {
    EXPECT_EQ(shippedCutChartsText(), readText(kShipped));
    EXPECT_EQ(shippedCutCharts(), loadCutChartsFile(kShipped));
}

TEST(CutChart, PickAtARowGivesTheRowExactly) {
    const CutChartSet set = loadCutChartsFile(kShipped);
    for (const CutChart& c : set.charts)
        for (const CutRow& r : c.rows) {
            const CutPick pick =
                pickCutRow(set, c.process, c.material, c.consumable, r.thicknessMm());
            ASSERT_TRUE(pick.ok()) << pick.outcome.message;
            EXPECT_EQ(pick.row, r) << c.name() << " at " << r.thicknessMm();
            EXPECT_EQ(pick.chart, &c);
        }
}

// Between two rows every figure of the chart lies between the neighbours' and on the straight
// line through them: the pick at t equals a + (t - ta) / (tb - ta) * (b - a), computed here
// independently from the neighbours found by a linear scan.
TEST(CutChart, PickBetweenRowsIsLinearInThickness) {
    CutChartSet set = loadCutChartsFile(kShipped);
    const CutChartSet extra = fullSet();
    set.charts.insert(set.charts.end(), extra.charts.begin(), extra.charts.end());
    std::mt19937 rng(20240624);
    int checked = 0;
    for (const CutChart& c : set.charts) {
        const double lo = c.rows.front().thicknessMm(), hi = c.rows.back().thicknessMm();
        std::uniform_real_distribution<double> pickT(lo, hi);
        for (int n = 0; n < 200; ++n) {
            const double t = pickT(rng);
            std::size_t b = 1;
            while (c.rows[b].thicknessMm() < t)
                ++b;
            const CutRow &ra = c.rows[b - 1], &rb = c.rows[b];
            const double w = (t - ra.thicknessMm()) / (rb.thicknessMm() - ra.thicknessMm());
            const CutPick pick = pickCutRow(c, t);
            ASSERT_TRUE(pick.ok()) << pick.outcome.message;
            EXPECT_EQ(pick.row.thicknessMm(), t);
            for (const CutFigure f : c.columns) {
                const double va = *ra.get(f), vb = *rb.get(f), v = *pick.row.get(f);
                EXPECT_GE(v, std::min(va, vb) - 1e-9) << c.name() << " " << cutFigureInfo(f).key;
                EXPECT_LE(v, std::max(va, vb) + 1e-9) << c.name() << " " << cutFigureInfo(f).key;
                EXPECT_NEAR(v, va + w * (vb - va), 1e-9 * (1.0 + std::fabs(va) + std::fabs(vb)))
                    << c.name() << " " << cutFigureInfo(f).key << " at " << t;
                ++checked;
            }
            for (std::size_t k = 0; k < kCutFigureCount; ++k) {
                const auto f = static_cast<CutFigure>(k);
                EXPECT_EQ(pick.row.get(f).has_value(), ra.get(f).has_value())
                    << "a figure the chart does not give must stay absent: "
                    << cutFigureInfo(f).key;
            }
        }
    }
    EXPECT_GT(checked, 2000);
}

TEST(CutChart, KnownValuesBetweenRows) {
    const CutChartSet set = parseCutCharts(doc(kPlasma));
    const CutPick mid = pickCutRow(set, CutProcess::Plasma, "mild_steel", "45A", 2.0);
    ASSERT_TRUE(mid.ok()) << mid.outcome.message;
    EXPECT_DOUBLE_EQ(*mid.row.get(CutFigure::CutSpeedMmMin), 6000.0);
    EXPECT_DOUBLE_EQ(*mid.row.get(CutFigure::KerfMm), 1.35);
    EXPECT_DOUBLE_EQ(*mid.row.get(CutFigure::ArcVoltageV), 115.0);
    const CutPick quarter = pickCutRow(set, CutProcess::Plasma, "mild_steel", "45A", 3.75);
    ASSERT_TRUE(quarter.ok());
    EXPECT_DOUBLE_EQ(*quarter.row.get(CutFigure::CutSpeedMmMin), 3375.0);
    EXPECT_FALSE(quarter.row.get(CutFigure::PreheatS).has_value());
}

TEST(CutChart, ThicknessOutsideTheChartIsRefusedWithItsRange) {
    const CutChartSet set = loadCutChartsFile(kShipped);
    const CutPick above =
        pickCutRow(set, CutProcess::Plasma, "mild_steel", "Powermax65/85 45A shielded", 12.7);
    EXPECT_TRUE(above.outcome.refused());
    EXPECT_EQ(above.outcome.key, "process.thickness_mm");
    EXPECT_EQ(above.outcome.message, "12.7 mm is outside the chart 'plasma / mild_steel / "
                                     "Powermax65/85 45A shielded': 0.5 .. 6 mm");
    ASSERT_NE(above.chart, nullptr);

    const CutPick below =
        pickCutRow(set, CutProcess::Plasma, "mild_steel", "Powermax85 85A shielded", 2.5);
    EXPECT_TRUE(below.outcome.refused());
    EXPECT_TRUE(has(below.outcome.message, "2.5 mm is outside")) << below.outcome.message;
    EXPECT_TRUE(has(below.outcome.message, ": 3 .. 20 mm")) << below.outcome.message;

    // Just inside both ends is fine; NaN is refused.
    const CutChart& c = set.charts.front();
    EXPECT_TRUE(pickCutRow(c, c.rows.front().thicknessMm()).ok());
    EXPECT_TRUE(pickCutRow(c, c.rows.back().thicknessMm()).ok());
    EXPECT_FALSE(pickCutRow(c, std::nextafter(c.rows.back().thicknessMm(), 1e9)).ok());
    EXPECT_FALSE(pickCutRow(c, std::numeric_limits<double>::quiet_NaN()).ok());
}

TEST(CutChart, UnknownMaterialConsumableOrProcessIsRefusedWithTheKnownOnes) {
    const CutChartSet set = loadCutChartsFile(kShipped);
    const CutPick m = pickCutRow(set, CutProcess::Plasma, "brass", "x", 3.0);
    EXPECT_TRUE(m.outcome.refused());
    EXPECT_EQ(m.outcome.key, "process.material");
    EXPECT_TRUE(has(m.outcome.message, "\"brass\"")) << m.outcome.message;
    EXPECT_TRUE(has(m.outcome.message, "mild_steel, stainless_steel")) << m.outcome.message;

    const CutPick c = pickCutRow(set, CutProcess::Plasma, "mild_steel", "125A", 3.0);
    EXPECT_TRUE(c.outcome.refused());
    EXPECT_EQ(c.outcome.key, "process.consumable");
    EXPECT_TRUE(has(c.outcome.message, "Powermax85 85A shielded")) << c.outcome.message;
    EXPECT_TRUE(has(c.outcome.message, "'plasma / mild_steel / 125A'")) << c.outcome.message;

    const CutChartSet plasmaOnly = parseCutCharts(doc(kPlasma));
    const CutPick p = pickCutRow(plasmaOnly, CutProcess::Laser, "mild_steel", "45A", 3.0);
    EXPECT_TRUE(p.outcome.refused());
    EXPECT_TRUE(has(p.outcome.message, "no cut chart for laser")) << p.outcome.message;
    EXPECT_TRUE(has(p.outcome.message, "plasma")) << p.outcome.message;
}

TEST(CutChart, TheBaseDocumentOfTheRefusalTestsIsValid) {
    EXPECT_EQ(parseError(doc(kPlasma)), "");
}

TEST(CutChart, UnknownKeysAreRefusedNamingThem) {
    EXPECT_TRUE(has(parseError(doc(kPlasma, R"("comment": "x", )")), "unknown key \"comment\""));
    std::string chart = kPlasma;
    chart.insert(1, R"("kerf": 1.2, )");
    const std::string e = parseError(doc(chart));
    EXPECT_TRUE(has(e, "unknown key \"kerf\"")) << e;
    EXPECT_TRUE(has(e, "plasma / mild_steel / 45A")) << e;

    std::string col = kPlasma;
    col.replace(col.find("\"kerf_mm\""), 9, "\"kerf\"");
    const std::string ec = parseError(doc(col));
    EXPECT_TRUE(has(ec, "columns[2] = \"kerf\" is not a figure")) << ec;
}

TEST(CutChart, ValuesOutsideTheirRangeAreRefusedWithFieldValueUnitAndLimit) {
    auto withRow = [](const std::string& row) {
        std::string chart = kPlasma;
        chart.replace(chart.find("[3, 4000, 1.5, 120]"), 19, row);
        return parseError(doc(chart));
    };
    const std::string kerf = withRow("[3, 4000, 12, 120]");
    EXPECT_TRUE(has(kerf, "cut chart 'plasma / mild_steel / 45A' (charts[0]) rows[1]")) << kerf;
    EXPECT_TRUE(has(kerf, "kerf_mm = 12 mm is outside [0.05, 10] mm")) << kerf;
    EXPECT_TRUE(has(withRow("[3, 0, 1.5, 120]"),
                    "cut_speed_mm_min = 0 mm/min is outside (0, 100000] mm/min"));
    EXPECT_TRUE(has(withRow("[3, 4000, 1.5, 1000]"), "arc_voltage_v = 1000 V is outside"));
    EXPECT_TRUE(has(withRow("[400, 4000, 1.5, 120]"), "thickness_mm = 400 mm is outside"));
    EXPECT_TRUE(has(withRow("[3, 4000, 1.5]"), "rows[1] must be an array of 4 numbers"));
    EXPECT_TRUE(has(withRow("[3, 4000, null, 120]"), "kerf_mm must be a number, found null"));
    // A number beyond a double is a JSON error, with its line.
    EXPECT_TRUE(has(withRow("[3, 4000, 1e999, 120]"), "cut charts: "));

    std::string life = kPlasma;
    life.insert(1, R"("life_pierces": 2.5, )");
    EXPECT_TRUE(has(parseError(doc(life)), "life_pierces = 2.5 pierces is not a whole number"));
    std::string vpm = kPlasma;
    vpm.insert(1, R"("volts_per_mm": 80, )");
    EXPECT_TRUE(has(parseError(doc(vpm)), "volts_per_mm = 80 V/mm is outside [0.1, 50] V/mm"));
}

TEST(CutChart, NaNAndInfinityAreRefusedNamingTheField) {
    CutChartSet set = fullSet();
    ASSERT_EQ(checkError(set), "");
    set.charts[0].rows[2].set(CutFigure::KerfMm, std::numeric_limits<double>::quiet_NaN());
    const std::string e = checkError(set);
    EXPECT_TRUE(has(e, "rows[2]: kerf_mm = NaN mm is outside [0.05, 10] mm")) << e;
    EXPECT_THROW(writeCutCharts(set), CutChartError);

    CutChartSet inf = fullSet();
    inf.charts[1].rows[0].set(CutFigure::PreheatS, std::numeric_limits<double>::infinity());
    EXPECT_TRUE(has(checkError(inf), "preheat_s = Inf s is outside [0, 600] s"));

    CutChartSet life = fullSet();
    life.charts[0].life_arc_minutes = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(has(checkError(life), "life_arc_minutes = NaN min"));
}

TEST(CutChart, ThicknessesMustIncreaseStrictly) {
    std::string same = kPlasma;
    same.replace(same.find("[3, 4000"), 2, "[1");
    const std::string e = parseError(doc(same));
    EXPECT_TRUE(has(e, "rows[1]: thickness_mm = 1 mm is not above rows[0]'s 1 mm")) << e;
    std::string down = kPlasma;
    down.replace(down.find("[6, 1500"), 2, "[2");
    EXPECT_TRUE(has(parseError(doc(down)), "strictly increasing thickness"));
}

TEST(CutChart, ARepeatedChartIsRefused) {
    const std::string e = parseError(doc(kPlasma + ", " + kPlasma));
    EXPECT_TRUE(has(e, "(charts[1]) repeats charts[0]")) << e;
    // Another consumable set of the same material is a different chart.
    std::string other = kPlasma;
    other.replace(other.find("\"45A\""), 5, "\"65A\"");
    EXPECT_EQ(parseError(doc(kPlasma + ", " + other)), "");
}

TEST(CutChart, ProcessSpecificFiguresAndRequiredKeys) {
    std::string oxy = kPlasma;
    oxy.replace(oxy.find("\"plasma\""), 8, "\"oxy_fuel\"");
    EXPECT_TRUE(has(parseError(doc(oxy)),
                    "arc_voltage_v is a figure of plasma charts only; this chart is oxy_fuel"));
    std::string pre = kPlasma;
    pre.replace(pre.find("\"arc_voltage_v\""), 15, "\"preheat_s\"");
    EXPECT_TRUE(has(parseError(doc(pre)), "preheat_s is a figure of oxy_fuel charts only"));
    std::string noSpeed = kPlasma;
    noSpeed.replace(noSpeed.find("\"cut_speed_mm_min\""), 18, "\"pierce_delay_s\"");
    EXPECT_TRUE(has(parseError(doc(noSpeed)), "columns must include cut_speed_mm_min"));
    std::string noSource = kPlasma;
    noSource.replace(noSource.find("\"test\""), 6, "\" \"");
    EXPECT_TRUE(has(parseError(doc(noSource)), "source must say where the figures come from"));
    std::string typ = kPlasma;
    typ.replace(typ.find("true"), 4, "\"yes\"");
    EXPECT_TRUE(has(parseError(doc(typ)), "typical_values must be true or false"));
    EXPECT_TRUE(has(parseError(R"({"format": "cutcell-cut-charts", "version": 2, "charts": []})"),
                    "version = 2 is not supported"));
    EXPECT_TRUE(has(parseError(R"({"version": 1, "charts": []})"), "missing key format"));
}

TEST(CutChart, WriteThenParseGivesTheSameSet) {
    const CutChartSet set = fullSet();
    const std::string text = writeCutCharts(set);
    const CutChartSet back = parseCutCharts(text);
    EXPECT_EQ(back, set);
    EXPECT_EQ(writeCutCharts(back), text);
    // The process-specific figures of the oxy-fuel and laser charts are picked too.
    const CutPick oxy = pickCutRow(back, CutProcess::OxyFuel, "mild_steel", "tip 1", 9.0);
    ASSERT_TRUE(oxy.ok()) << oxy.outcome.message;
    EXPECT_DOUBLE_EQ(*oxy.row.get(CutFigure::PreheatS), 11.0);
    EXPECT_DOUBLE_EQ(oxy.row.cutSpeedMmMin(), 710.0);
    EXPECT_FALSE(oxy.row.get(CutFigure::ArcVoltageV).has_value());
    const CutPick laser = pickCutRow(back, CutProcess::Laser, "mild_steel", "3 kW O2", 3.0);
    ASSERT_TRUE(laser.ok());
    EXPECT_DOUBLE_EQ(laser.row.cutSpeedMmMin(), 6000.0);
}

TEST(CutChart, RowsThatDoNotMatchTheColumnsAreRefused) {
    CutChartSet extra = fullSet();
    extra.charts[2].rows[1].set(CutFigure::KerfMm, 0.2);
    EXPECT_TRUE(has(checkError(extra), "kerf_mm is given but is not a column of the chart"));
    CutChartSet missing = fullSet();
    missing.charts[1].rows[0].figures[static_cast<std::size_t>(CutFigure::PreheatS)].reset();
    EXPECT_TRUE(has(checkError(missing), "preheat_s is missing"));
}

} // namespace
} // namespace cutcell
