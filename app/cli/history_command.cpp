// cutcell-cli history: the runs of the production record (devices/record/), filtered by day,
// machine and outcome; a table, JSON or CSV.
#include "cli_commands.h"
#include "record_text.h"

#include "core/common/c_format.h"
#include "core/json/json.h"
#include "devices/record/run_record_store.h"

#include <cstdio>
#include <filesystem>
#include <string>

namespace cutcell::cli {
namespace {

json::Value parsedOrNull(const std::string& text) {
    if (text.empty()) return {};
    try {
        return json::parse(text);
    } catch (const std::exception&) {
        return text;
    }
}

} // namespace

int runHistory(const HistoryOptions& o) {
    RunQuery q;
    q.machine = o.machine;
    q.outcome = o.outcome;
    if (!o.since.empty() && !parseDay(o.since, &q.since_ms)) {
        std::fprintf(stderr, "history: --since %s is not a day (YYYY-MM-DD)\n", o.since.c_str());
        return kUsage;
    }
    const std::string path = o.db.empty() ? RunRecordStore::defaultPath() : o.db;
    if (!isPostgresConnection(path) && !std::filesystem::exists(path)) {
        std::fprintf(stderr,
                     "history: no production record at %s (the GUI records its runs there; "
                     "`cutcell-cli run --record FILE` adds a run to FILE)\n",
                     path.c_str());
        return kFailure;
    }
    std::vector<RecordedRun> runs;
    std::string where;
    try {
        const RunRecordStore record(path, {});
        runs = record.runs(q);
        where = record.where();
    } catch (const RecordError& e) {
        std::fprintf(stderr, "history: %s\n", e.what());
        return kFailure;
    }
    if (o.json) {
        json::Array out;
        for (const RecordedRun& r : runs)
            out.emplace_back(json::Object{{"id", static_cast<double>(r.id)},
                                          {"machine", r.machine},
                                          {"job", r.job_name},
                                          {"job_hash", r.job_hash},
                                          {"operator", r.operator_name},
                                          {"started", utcTime(r.started_ms)},
                                          {"ended", utcTime(r.ended_ms)},
                                          {"outcome", r.outcome},
                                          {"cycle_time_s", r.cycle_time_s},
                                          {"made", parsedOrNull(r.made_json)},
                                          {"stop", parsedOrNull(r.stop_json)},
                                          {"alarms", r.alarms},
                                          {"run_dir", r.run_dir}});
        std::printf("%s\n", json::write(json::Value(std::move(out))).c_str());
        return kOk;
    }
    if (o.csv) {
        std::printf("id,machine,job,job_hash,operator,started,ended,outcome,cycle_time_s,alarms,"
                    "run_dir\n");
        for (const RecordedRun& r : runs)
            std::printf("%lld,%s,%s,%s,%s,%s,%s,%s,%s,%d,%s\n", static_cast<long long>(r.id),
                        csvField(r.machine).c_str(), csvField(r.job_name).c_str(),
                        r.job_hash.c_str(), csvField(r.operator_name).c_str(),
                        utcTime(r.started_ms).c_str(), utcTime(r.ended_ms).c_str(),
                        csvField(r.outcome).c_str(), formatC("%.3f", r.cycle_time_s).c_str(),
                        r.alarms, csvField(r.run_dir).c_str());
        return kOk;
    }
    std::printf("%-5s %-20s %-21s %-12s %10s %6s  %s\n", "id", "started (UTC)", "machine",
                "outcome", "cycle (s)", "alarms", "job");
    for (const RecordedRun& r : runs)
        std::printf("%-5lld %-20s %-21s %-12s %10s %6d  %s\n", static_cast<long long>(r.id),
                    utcTime(r.started_ms).c_str(), r.machine.c_str(),
                    r.outcome.empty() ? "running" : r.outcome.substr(0, 12).c_str(),
                    r.ended_ms ? formatC("%.1f", r.cycle_time_s).c_str() : "-", r.alarms,
                    r.job_name.c_str());
    std::printf("%zu run(s) in %s\n", runs.size(), where.c_str());
    return kOk;
}

} // namespace cutcell::cli
