// cutcell-cli compare: a machine's two cutting methods side by side (seed 000, Fig. 11-14),
// through MachineModule::compareMethods. A job for a machine without both methods (its module
// refuses the variants static_pipe and rotating_pipe) exits 64 with why. Writes into DIR as one
// unit (writeFolderSet): comparison.json, comparison.md and each figure as SVG (the core's) and
// PNG (chart_png.cpp, when built with Qt Gui).
#include "cli_commands.h"

#include "core/job/file_set.h"
#include "core/machine/machine_registry.h"

#ifdef CUTCELL_HAVE_CHART_PNG
#include "chart_png.h"
#endif

#include <cstdio>
#include <filesystem>

namespace cutcell::cli {

int runCompare(const CompareOptions& o) {
    Job job;
    int code = kOk;
    if (!loadJobArg(o.job, job, &code)) return code;
    const MachineModule& module = machineFor(job);
    // The methods decide, not the machine's id: both variants must be the module's.
    for (const char* variant : {"static_pipe", "rotating_pipe"}) {
        Job probe = job;
        if (const Outcome v = module.setVariant(probe, variant); !v.ok()) {
            std::fprintf(stderr,
                         "cutcell-cli compare: compares the methods static_pipe and "
                         "rotating_pipe, which the job's machine \"%s\" does not both have: "
                         "%s\n",
                         module.id().c_str(), v.message.c_str());
            return kUsage;
        }
    }
    MethodComparisonFiles result;
    const Outcome done = module.compareMethods(job, &result);
    if (done.refused()) {
        std::fprintf(stderr, "cutcell-cli compare: %s\n", done.message.c_str());
        return kUsage;
    }
    const std::string dir =
        !o.out.empty() ? o.out : "compare-" + std::filesystem::path(o.job).stem().string();
    try {
        std::vector<FileContents> files{{"comparison.json", result.json},
                                        {"comparison.md", result.markdown}};
#ifdef CUTCELL_HAVE_CHART_PNG
        const auto app = ensureGuiApplication();
#endif
        for (const auto& [stem, chart] : result.charts) {
            files.push_back({stem + ".svg", lineChartSvg(chart)});
#ifdef CUTCELL_HAVE_CHART_PNG
            files.push_back({stem + ".png", chartPng(chart)});
#endif
        }
        writeFolderSet(dir, files);
        for (const FileContents& f : files)
            std::printf("wrote %s (%zu bytes)\n",
                        (std::filesystem::path(dir) / f.path).string().c_str(), f.contents.size());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "cutcell-cli compare: %s\n", e.what());
        return kFailure;
    }
    std::printf("\n%s", result.markdown.c_str());
    if (!done.ok()) {
        std::fprintf(stderr, "cutcell-cli compare: %s\n", done.message.c_str());
        return kUnreachable;
    }
    return kOk;
}

} // namespace cutcell::cli
