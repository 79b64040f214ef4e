// cutcell-cli export: the files a machine offers (its module's exports()).
#include "cli_commands.h"

#include "core/job/file_set.h"
#include "core/job/job_io.h"
#include "core/machine/machine_registry.h"

#include <cstdio>
#include <filesystem>
#include <utility>

namespace cutcell::cli {

int runExport(const ExportOptions& o) {
    Job job;
    int code = kOk;
    if (!loadJobArg(o.job, job, &code)) return code;
    const MachineModule& module = machineFor(job);
    // Export id -> the file given for it (main.cpp declares one option per export id).
    const std::pair<const char*, const std::string*> kFiles[] = {{"gcode", &o.gcode},
                                                                 {"template_svg", &o.template_svg},
                                                                 {"template_pdf", &o.template_pdf},
                                                                 {"path_csv", &o.path_csv},
                                                                 {"joints_csv", &o.joints_csv}};
    std::vector<std::pair<std::string, std::string>> wanted; // export id, file
    for (const auto& [id, file] : kFiles)
        if (!file->empty()) wanted.emplace_back(id, *file);
    if (wanted.empty()) {
        std::fprintf(stderr, "cutcell-cli export: give at least one of --gcode FILE, "
                             "--template-svg FILE, --template-pdf FILE, --path-csv FILE, "
                             "--joints-csv FILE\n");
        return kUsage;
    }
    const auto offered = module.exports();
    std::string offeredList;
    for (const auto& e : offered)
        offeredList += (offeredList.empty() ? "" : ", ") + e.id;
    for (const auto& [id, file] : wanted) {
        bool found = false;
        for (const auto& e : offered)
            found = found || e.id == id;
        if (!found) {
            std::string others; // the machines that do offer it
            for (const MachineModule* m : machines())
                for (const auto& e : m->exports())
                    if (e.id == id) others += (others.empty() ? "\"" : ", \"") + m->id() + "\"";
            std::fprintf(
                stderr,
                "cutcell-cli export: machine \"%s\" offers no %s export (it offers: %s)%s\n",
                module.id().c_str(), id.c_str(), offeredList.c_str(),
                others.empty() ? "" : ("; machine.kind " + others + " does").c_str());
            return kInvalidJob;
        }
    }
    try {
        const MachinePlan plan = module.plan(job, {});
        if (!plan.ok()) {
            std::fprintf(stderr, "cutcell-cli export: %s\n", plan.outcome.message.c_str());
            return kUnreachable;
        }
        // Every file asked for as one unit: a kill leaves the old files or the new ones.
        std::vector<FileContents> files;
        for (const auto& [id, file] : wanted)
            files.push_back({file, module.exportFileWith(id, job, plan, {o.paper})});
        writeFileSet(files);
        for (size_t i = 0; i < files.size(); ++i)
            for (const auto& e : offered)
                if (e.id == wanted[i].first)
                    std::printf("wrote %s (%s, %zu bytes)\n", files[i].path.c_str(),
                                e.title.c_str(), files[i].contents.size());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "cutcell-cli export: %s\n", e.what());
        return kFailure;
    }
    return kOk;
}

} // namespace cutcell::cli
