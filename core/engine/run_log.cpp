#include "core/engine/run_log.h"
#include "core/common/c_format.h"

#include "core/job/job_io.h"
#include "core/json/json.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <filesystem>

namespace cutcell {

namespace fs = std::filesystem;

RunLog::~RunLog() {
    if (file_) std::fclose(file_);
}

void RunLog::openFile(const std::string& path) {
    if (file_) std::fclose(file_);
    file_ = std::fopen(path.c_str(), "a");
    if (!file_) problem("cannot open " + path + ": " + std::strerror(errno));
}

void RunLog::problem(const std::string& what) {
    // Once each, not once per event.
    if (std::find(reported_.begin(), reported_.end(), what) != reported_.end()) return;
    reported_.push_back(what);
    problem_ = what + " (runs are not logged)";
    std::fprintf(stderr, "warning: run log: %s\n", problem_.c_str());
}

std::string RunLog::formatEvent(const EngineEvent& e) {
    char stamp[40] = "";
    const std::time_t secs = static_cast<std::time_t>(e.wall_ms / 1000);
    std::tm tm{};
    gmtime_r(&secs, &tm);
    std::strftime(stamp, sizeof stamp, "%Y-%m-%dT%H:%M:%S", &tm);
    const char* sev = e.severity == Severity::Info      ? "info"
                      : e.severity == Severity::Warning ? "warn"
                                                        : "ERROR";
    char line[420];
    snprintfC(line, sizeof line, "%s.%03dZ t=%.3f s %-5s %-11s %s -> %s: %s", stamp,
              static_cast<int>(e.wall_ms % 1000), e.time_s, sev, toString(e.kind), toString(e.from),
              toString(e.to), e.text.data());
    return line;
}

namespace {

std::int64_t unixMsNow() {
    return std::chrono::duration_cast<std::chrono::milliseconds>(
               std::chrono::system_clock::now().time_since_epoch())
        .count();
}

} // namespace

template <class F> void RunLog::tellRecord(F&& call) {
    if (!sink_) return;
    try {
        call(*sink_);
    } catch (const std::exception& e) {
        problem(std::string("production record: ") + e.what());
    }
}

void RunLog::beginRun(std::uint32_t runId, const std::string& jobName, const std::string& jobText) {
    beginRunFolder(runId, jobText);
    tellRecord([&](RunRecordSink& r) {
        r.opened({runId, jobName, jobText, dir_, unixMsNow()});
        recordOpen_ = true;
    });
}

void RunLog::beginRunFolder(std::uint32_t runId, const std::string& jobText) {
    dir_.clear();
    if (runsDir_.empty()) return;
    char stamp[32];
    const std::time_t now = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&now, &tm);
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &tm);
    fs::path dir = fs::path(runsDir_) / (std::string(stamp) + "-run" + std::to_string(runId));
    for (int k = 2; fs::exists(dir); ++k)
        dir = fs::path(runsDir_) /
              (std::string(stamp) + "-run" + std::to_string(runId) + "-" + std::to_string(k));
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) return problem("cannot create " + dir.string() + ": " + ec.message());
    dir_ = dir.string();
    names_ = {};
    try {
        writeFileAtomically((dir / "job.json").string(), jobText);
    } catch (const std::exception&) {
        // The events still go to events.log; a missing job.json is visible in the folder.
    }
    openFile((dir / "events.log").string());
    runOpen_ = true;
}

void RunLog::event(const EngineEvent& e) {
    if (recordOpen_ && e.kind == EventKind::CutEnded)
        tellRecord([&](RunRecordSink& r) {
            r.cutEnded({e.wall_ms, e.cut_tool_on_s, e.cut_length_mm});
        });
    if (recordOpen_ && e.severity != Severity::Info)
        tellRecord([&](RunRecordSink& r) {
            r.alarm({e.wall_ms,
                     e.kind == EventKind::Fault      ? "fault"
                     : e.severity == Severity::Error ? "error"
                                                     : "warning",
                     e.text.data()});
        });
    if (runsDir_.empty()) return;
    if (!file_) {
        std::error_code ec;
        fs::create_directories(runsDir_, ec);
        if (ec) return problem("cannot create " + runsDir_ + ": " + ec.message());
        openFile((fs::path(runsDir_) / "engine.log").string());
        if (!file_) return;
    }
    const std::string line = formatEvent(e);
    std::fputs(line.c_str(), file_);
    std::fputc('\n', file_);
    std::fflush(file_); // nothing is lost if the program dies after this line
}

void RunLog::eventForLastRun(const EngineEvent& e) {
    // Not "if a file is open": an event after the run's end opens engine.log, and the line
    // that says why the program ended went there, not to the run it ended (seen in CI under
    // load: the E-STOP's events still in the ring when the SIGTERM line came).
    if (runOpen_ || dir_.empty()) {
        event(e);
        return;
    }
    std::FILE* f = std::fopen((fs::path(dir_) / "events.log").string().c_str(), "a");
    if (!f) {
        event(e);
        return;
    }
    std::fputs((formatEvent(e) + "\n").c_str(), f);
    std::fclose(f);
}

void RunLog::endRun(const std::string& outcome, const TrackingReport& report, const CycleStats& c,
                    const RunStopPoint& stop, const RunStopPoint& start, const RunStopPoint& end) {
    if (!recordOpen_ && (runsDir_.empty() || dir_.empty())) return;
    json::Object cycle{{"period_s", c.period_s},
                       {"cycles", static_cast<double>(c.cycles)},
                       {"overruns", static_cast<double>(c.overruns)},
                       {"missed_deadlines", static_cast<double>(c.missed_deadlines)},
                       {"work_us_max", c.work_us_max},
                       {"jitter_us_p50", c.jitter_us_p50},
                       {"jitter_us_p99", c.jitter_us_p99},
                       {"jitter_us_max", c.jitter_us_max},
                       {"telemetry_dropped", static_cast<double>(c.telemetry_dropped)},
                       {"events_dropped", static_cast<double>(c.events_dropped)},
                       {"last_estop_latency_us", c.last_estop_latency_us}};
    json::Object top{
        {"outcome", outcome}, {"tracking", reportToJson(report, &names_)}, {"cycle", cycle}};
    if (stop.valid)
        top.emplace_back("stop",
                         json::Object{{"path_time_s", stop.path_time_s},
                                      {"progress", stop.progress},
                                      {"length_mm", stop.length_mm},
                                      {"elapsed_s", stop.elapsed_s},
                                      {"point_index", static_cast<double>(stop.point_index)},
                                      {"point_count", static_cast<double>(stop.point_count)},
                                      {"counts", toString(terms_.counts)}});
    if (start.valid)
        top.emplace_back(
            "recovered_from",
            json::Object{{"path_time_s", start.path_time_s},
                         {"progress", start.progress},
                         {"point_index", static_cast<double>(start.point_index)},
                         {"point_count", static_cast<double>(start.point_count)},
                         {"not_cut_before_mm", start.length_mm},
                         {"note", "a cut recovery: this run cut the path from this point on; "
                                  "the path before it was not cut by this run"}});
    if (end.valid) {
        // The run's time on the engine's clock, from Start to its end (the cycle time).
        top.emplace_back("elapsed_s", end.elapsed_s);
        top.emplace_back("made", madeToJson(terms_, end));
        top.emplace_back("tool", json::Object{{"starts", static_cast<double>(end.tool_starts)},
                                              {"on_s", end.tool_on_s}});
    }
    const json::Value doc(std::move(top));
    const std::string summary = json::write(doc);
    if (recordOpen_) {
        recordOpen_ = false;
        tellRecord([&](RunRecordSink& r) { r.closed({outcome, unixMsNow(), summary}); });
    }
    if (runsDir_.empty() || dir_.empty()) return;
    try {
        writeFileAtomically((fs::path(dir_) / "summary.json").string(), summary);
    } catch (const std::exception&) {
    }
    if (file_) {
        std::fclose(file_);
        file_ = nullptr;
    }
    runOpen_ = false;
}

json::Value RunLog::madeToJson(const RunTerms& terms, const RunStopPoint& end) {
    json::Object made{{"counts", toString(terms.counts)},
                      {madeNounPlural(terms.counts), static_cast<double>(end.made)},
                      {"of", static_cast<double>(end.point_count)}};
    if (terms.path_length) made.emplace_back("length_mm", end.length_mm);
    if (terms.counts == WorkCount::Pieces) {
        // As ordered: a queue changed during the run is not followed here.
        json::Array lengths;
        for (std::uint32_t k = 0; k < end.made && k < terms.piece_lengths_mm.size(); ++k)
            lengths.emplace_back(terms.piece_lengths_mm[k]);
        made.emplace_back("lengths_mm", std::move(lengths));
    }
    return made;
}

} // namespace cutcell
