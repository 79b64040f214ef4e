// cutcell-cli materials: the cut-chart table (core/process/cut_chart.h) in use - the user's
// (core/process/cut_chart_library.h) when it exists, else the shipped one - or a file: every
// chart with its thickness range, figures and source, or one row picked for a thickness
// (interpolated between the chart's rows, refused outside them), or one edit (--set, --add-row,
// --remove-row) checked as the reader checks and written back atomically.
#include "cli_commands.h"

#include "core/common/c_format.h"
#include "core/json/json.h"
#include "core/process/cut_chart.h"
#include "core/process/cut_chart_library.h"

#include <cstdio>
#include <optional>
#include <string>
#include <vector>

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

// The process, material, consumable and thickness that start --set, --add-row and --remove-row.
struct RowAddress {
    CutProcess process = CutProcess::Plasma;
    std::string material, consumable;
    double thickness_mm = 0;
};

std::optional<RowAddress> rowAddress(const std::vector<std::string>& args, const char* option) {
    const auto process = cutProcessFromString(args[0]);
    if (!process) {
        std::fprintf(stderr,
                     "cutcell-cli materials: %s: process '%s' is not one of plasma, oxy_fuel, "
                     "laser\n",
                     option, args[0].c_str());
        return std::nullopt;
    }
    const auto thickness = parseDouble(args[3]);
    if (!thickness) {
        std::fprintf(stderr,
                     "cutcell-cli materials: %s: thickness '%s' is not a number of mm (a "
                     "decimal point, not a comma)\n",
                     option, args[3].c_str());
        return std::nullopt;
    }
    return RowAddress{*process, args[1], args[2], *thickness};
}

std::optional<CutFigure> figureArg(const std::string& key, const char* option) {
    if (const auto f = cutFigureFromKey(key)) return f;
    std::string all;
    for (std::size_t k = 0; k < kCutFigureCount; ++k)
        all +=
            (all.empty() ? "" : ", ") + std::string(cutFigureInfo(static_cast<CutFigure>(k)).key);
    std::fprintf(stderr, "cutcell-cli materials: %s: '%s' is not a figure (one of %s)\n", option,
                 key.c_str(), all.c_str());
    return std::nullopt;
}

std::optional<double> valueArg(const std::string& text, CutFigure f, const char* option) {
    if (const auto v = parseDouble(text)) return v;
    std::fprintf(stderr,
                 "cutcell-cli materials: %s: %s = '%s' is not a number of %s (a decimal point, "
                 "not a comma)\n",
                 option, cutFigureInfo(f).key, text.c_str(), cutFigureInfo(f).unit);
    return std::nullopt;
}

// One edit of the table read from `path` (or the shipped one, when the user's does not exist
// yet), written back to `path`.
int edit(const CutChartSet& set, const std::string& path, const MaterialsOptions& o) {
    CutChartSet edited;
    std::string done;
    std::optional<RowAddress> at;
    try {
        if (!o.set.empty()) {
            at = rowAddress(o.set, "--set");
            const auto f = at ? figureArg(o.set[4], "--set") : std::nullopt;
            const auto v = f ? valueArg(o.set[5], *f, "--set") : std::nullopt;
            if (!v) return kUsage;
            const std::size_t chart = findCutChart(set, at->process, at->material, at->consumable);
            const std::size_t row = findCutRow(set, chart, at->thickness_mm);
            const double was = *set.charts[chart].rows[row].get(*f);
            edited = setCutChartFigure(set, chart, row, *f, *v);
            done =
                formatC("%s at %g mm: %s %g -> %g %s", set.charts[chart].name().c_str(),
                        at->thickness_mm, cutFigureInfo(*f).key, was, *v, cutFigureInfo(*f).unit);
        } else if (!o.add_row.empty()) {
            at = rowAddress(o.add_row, "--add-row");
            if (!at) return kUsage;
            CutRow row;
            row.set(CutFigure::ThicknessMm, at->thickness_mm);
            for (std::size_t i = 4; i < o.add_row.size(); ++i) {
                const std::string& arg = o.add_row[i];
                const auto eq = arg.find('=');
                if (eq == std::string::npos) {
                    std::fprintf(stderr,
                                 "cutcell-cli materials: --add-row: '%s' is not FIGURE=VALUE "
                                 "(cut_speed_mm_min=2500)\n",
                                 arg.c_str());
                    return kUsage;
                }
                const auto f = figureArg(arg.substr(0, eq), "--add-row");
                if (!f) return kUsage;
                if (row.get(*f)) {
                    std::fprintf(stderr,
                                 "cutcell-cli materials: --add-row: %s is given twice (the "
                                 "thickness is THICKNESS_MM)\n",
                                 cutFigureInfo(*f).key);
                    return kUsage;
                }
                const auto v = valueArg(arg.substr(eq + 1), *f, "--add-row");
                if (!v) return kUsage;
                row.set(*f, *v);
            }
            const std::size_t chart = findCutChart(set, at->process, at->material, at->consumable);
            edited = addCutChartRow(set, chart, row);
            done = formatC("%s: a row at %g mm added (%zu rows)", set.charts[chart].name().c_str(),
                           at->thickness_mm, edited.charts[chart].rows.size());
        } else {
            at = rowAddress(o.remove_row, "--remove-row");
            if (!at) return kUsage;
            const std::size_t chart = findCutChart(set, at->process, at->material, at->consumable);
            edited = removeCutChartRow(set, chart, findCutRow(set, chart, at->thickness_mm));
            done =
                formatC("%s: the row at %g mm removed (%zu rows)", set.charts[chart].name().c_str(),
                        at->thickness_mm, edited.charts[chart].rows.size());
        }
    } catch (const CutChartError& e) {
        std::fprintf(stderr, "cutcell-cli materials: %s\n", e.what());
        return kInvalidJob;
    }
    try {
        saveCutChartsFile(path, edited);
    } catch (const CutChartFileError& e) {
        std::fprintf(stderr, "cutcell-cli materials: %s\n", e.what());
        return kFailure;
    } catch (const CutChartError& e) {
        std::fprintf(stderr, "cutcell-cli materials: %s\n", e.what());
        return kInvalidJob;
    }
    if (o.json) {
        const std::size_t chart = findCutChart(edited, at->process, at->material, at->consumable);
        std::fputs(json::write(json::Object{{"file", path},
                                            {"done", done},
                                            {"chart", chartSummaryJson(edited.charts[chart])}})
                       .c_str(),
                   stdout);
        return kOk;
    }
    std::printf("%s; written to %s\n", done.c_str(), path.c_str());
    return kOk;
}

} // namespace

int runMaterials(const MaterialsOptions& o) {
    const bool editing = !o.set.empty() || !o.add_row.empty() || !o.remove_row.empty();
    CutChartSet set;
    std::string path = o.file; // where an edit goes
    std::string which = "cut charts: " + o.file;
    try {
        if (!o.file.empty()) {
            set = loadCutChartsFile(o.file);
        } else {
            CutChartsInUse inUse = loadCutChartsInUse(defaultDataHome());
            set = std::move(inUse.set);
            path = inUse.path;
            which = inUse.user ? "cut charts: the user's table " + path
                               : "cut charts: the shipped table (an edit copies it to " + path +
                                     ", used from then on)";
        }
    } catch (const CutChartFileError& e) {
        std::fprintf(stderr, "cutcell-cli materials: %s\n", e.what());
        return kFailure;
    } catch (const CutChartError& e) {
        std::fprintf(stderr, "cutcell-cli materials: %s\n", e.what());
        return kInvalidJob;
    }
    if (editing) return edit(set, path, o);
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
    std::printf("%s\n", which.c_str());
    for (const CutChart& c : set.charts)
        printChart(c);
    return kOk;
}

} // namespace cutcell::cli
