// cutcell-cli materials: the cut-chart table (core/process/cut_chart.h), the shipped one or a
// file: every chart with its thickness range, figures and source, or one row picked for a
// thickness (interpolated between the chart's rows, refused outside them).
#include "cli_commands.h"

#include "core/common/c_format.h"
#include "core/json/json.h"
#include "core/process/cut_chart.h"

#include <cstdio>

namespace cutcell::cli {
namespace {

json::Value rowJson(const CutChart& chart, const CutRow& row) {
    json::Object o;
    for (CutFigure f : chart.columns)
        if (const auto v = row.get(f)) o.emplace_back(cutFigureInfo(f).key, *v);
    return o;
}

json::Value chartSummaryJson(const CutChart& c) {
    json::Array columns;
    for (CutFigure f : c.columns)
        columns.push_back(cutFigureInfo(f).key);
    return json::Object{{"process", toString(c.process)},
                        {"material", c.material},
                        {"consumable", c.consumable},
                        {"thickness_min_mm", c.rows.front().thicknessMm()},
                        {"thickness_max_mm", c.rows.back().thicknessMm()},
                        {"rows", static_cast<double>(c.rows.size())},
                        {"columns", columns},
                        {"typical_values", c.typical_values},
                        {"source", c.source}};
}

void printChart(const CutChart& c) {
    std::printf("%s\n", c.name().c_str());
    std::fputs(formatC("  thickness %g .. %g mm, %zu rows; figures:", c.rows.front().thicknessMm(),
                       c.rows.back().thicknessMm(), c.rows.size())
                   .c_str(),
               stdout);
    for (CutFigure f : c.columns)
        std::printf(" %s", cutFigureInfo(f).key);
    std::printf("\n  %s%s\n", c.typical_values ? "typical values; " : "", c.source.c_str());
}

void printRow(const CutChart& chart, const CutRow& row) {
    std::printf("%s\n", chart.name().c_str());
    for (CutFigure f : chart.columns)
        if (const auto v = row.get(f))
            std::fputs(
                formatC("  %-18s %g %s\n", cutFigureInfo(f).key, *v, cutFigureInfo(f).unit).c_str(),
                stdout);
}

int pick(const CutChartSet& set, const MaterialsOptions& o) {
    if (o.pick.size() != 4) {
        std::fprintf(stderr,
                     "cutcell-cli materials: --pick takes 4 values (PROCESS MATERIAL CONSUMABLE "
                     "THICKNESS_MM), got %zu\n",
                     o.pick.size());
        return kUsage;
    }
    const auto process = cutProcessFromString(o.pick[0]);
    if (!process) {
        std::fprintf(stderr,
                     "cutcell-cli materials: --pick: process '%s' is not one of plasma, oxy_fuel, "
                     "laser\n",
                     o.pick[0].c_str());
        return kUsage;
    }
    const auto thickness = parseDouble(o.pick[3]);
    if (!thickness) {
        std::fprintf(stderr,
                     "cutcell-cli materials: --pick: thickness '%s' is not a number of mm (a "
                     "decimal point, not a comma)\n",
                     o.pick[3].c_str());
        return kUsage;
    }
    const CutPick p = pickCutRow(set, *process, o.pick[1], o.pick[2], *thickness);
    if (!p.ok()) {
        std::fprintf(stderr, "cutcell-cli materials: %s: %s\n", p.outcome.key.c_str(),
                     p.outcome.message.c_str());
        return kInvalidJob;
    }
    if (o.json) {
        std::fputs(json::write(json::Object{{"chart", chartSummaryJson(*p.chart)},
                                            {"row", rowJson(*p.chart, p.row)}})
                       .c_str(),
                   stdout);
        return kOk;
    }
    printRow(*p.chart, p.row);
    return kOk;
}

} // namespace

int runMaterials(const MaterialsOptions& o) {
    CutChartSet set;
    try {
        set = o.file.empty() ? shippedCutCharts() : loadCutChartsFile(o.file);
    } catch (const CutChartFileError& e) {
        std::fprintf(stderr, "cutcell-cli materials: %s\n", e.what());
        return kFailure;
    } catch (const CutChartError& e) {
        std::fprintf(stderr, "cutcell-cli materials: %s\n", e.what());
        return kInvalidJob;
    }
    if (!o.pick.empty()) return pick(set, o);
    if (o.json) {
        json::Array charts;
        for (const CutChart& c : set.charts)
            charts.push_back(chartSummaryJson(c));
        std::fputs(json::write(json::Object{{"version", static_cast<double>(set.version)},
                                            {"charts", charts}})
                       .c_str(),
                   stdout);
        return kOk;
    }
    for (const CutChart& c : set.charts)
        printChart(c);
    return kOk;
}

} // namespace cutcell::cli
