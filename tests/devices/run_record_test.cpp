// The production record against real SQLite files: the schema from an empty file, a run of
// every machine through `cutcell-cli run --record` with the figures of its own summary.json,
// a program killed during a run (closed as interrupted at the next start, nothing else lost,
// integrity_check ok), a live program's run left open, and a newer schema refused.
#include "core/job/job_io.h"
#include "core/json/json.h"
#include "devices/record/sqlite_run_record.h"

#include <gtest/gtest.h>
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>

namespace cutcell {
namespace {

namespace fs = std::filesystem;

fs::path freshDir(const std::string& name) {
    const fs::path dir =
        fs::temp_directory_path() / ("cutcell_record_" + name + "_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

TEST(RunRecord, AnEmptyFileGetsTheSchemaAndARunRoundTrips) {
    const fs::path dir = freshDir("roundtrip");
    const std::string db = (dir / "sub" / "p.db").string(); // the folder is made too
    {
        SqliteRunRecord r(db, "ada");
        EXPECT_EQ(r.schemaVersion(), SqliteRunRecord::kSchemaVersion);
        EXPECT_EQ(r.interruptedAtOpen(), 0);
        const std::string job = R"({"schema": 2, "name": "x", "machine": {"kind": "flying_saw"}})";
        r.opened({7, "x", job, "/runs/a", 1'000'000});
        r.alarm({1'000'500, "fault", "axis 1 (carriage): following error"});
        r.closed({"fault: axis 1", 1'002'000,
                  R"({"outcome": "fault", "elapsed_s": 12.5, "stop": {"point_index": 3},)"
                  R"( "made": {"counts": "pieces", "pieces": 3}})"});
        const auto runs = r.runs({});
        ASSERT_EQ(runs.size(), 1u);
        EXPECT_EQ(runs[0].machine, "flying_saw");
        EXPECT_EQ(runs[0].operator_name, "ada");
        EXPECT_EQ(runs[0].outcome, "fault: axis 1");
        EXPECT_EQ(runs[0].started_ms, 1'000'000);
        EXPECT_EQ(runs[0].ended_ms, 1'002'000);
        EXPECT_DOUBLE_EQ(runs[0].cycle_time_s, 12.5); // the engine's clock, not the wall's 2 s
        EXPECT_EQ(json::parse(runs[0].made_json).find("pieces")->asNumber(), 3);
        EXPECT_EQ(json::parse(runs[0].stop_json).find("point_index")->asNumber(), 3);
        EXPECT_EQ(runs[0].alarms, 1);
        EXPECT_EQ(r.alarmsOf(runs[0].id).at(0).text, "axis 1 (carriage): following error");
        EXPECT_EQ(r.jobTextOf(runs[0].id), job);
        EXPECT_EQ(runs[0].job_hash, SqliteRunRecord::jobFingerprint(job));
        EXPECT_NE(runs[0].job_hash, SqliteRunRecord::jobFingerprint(job + " "));
        // Filters.
        EXPECT_EQ(r.runs({.machine = "pipe_robot_6axis"}).size(), 0u);
        EXPECT_EQ(r.runs({.since_ms = 1'000'001}).size(), 0u);
        EXPECT_EQ(r.runs({.outcome = "fault: axis 1"}).size(), 1u);
    }
    SqliteRunRecord again(db, "ada"); // reopening migrates nothing and keeps the run
    EXPECT_EQ(again.runs({}).size(), 1u);
    EXPECT_EQ(again.integrityCheck(), "ok");
    fs::remove_all(dir);
}

TEST(RunRecord, AKilledProgramsRunIsClosedAsInterruptedAndALiveOnesStaysOpen) {
    const fs::path dir = freshDir("killed");
    const std::string db = (dir / "p.db").string();
    {
        SqliteRunRecord r(db, "op");
        r.opened({1, "done", "{}", "", 1000});
        r.closed({"completed", 2000, "{}"});
    }
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        SqliteRunRecord r(db, "op");
        r.opened({2, "killed mid-run", "{}", "", 3000});
        r.alarm({3100, "warning", "a note before the kill"});
        raise(SIGKILL);
        _exit(0);
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);

    SqliteRunRecord live(db, "op"); // this process: its own open run must survive a reader
    EXPECT_EQ(live.interruptedAtOpen(), 1);
    live.opened({3, "running here", "{}", "", 4000});
    const SqliteRunRecord reader(db, "");
    EXPECT_EQ(reader.interruptedAtOpen(), 0) << "a running program's run was closed";
    const auto runs = reader.runs({});
    ASSERT_EQ(runs.size(), 3u);
    EXPECT_EQ(runs[0].outcome, "completed");
    EXPECT_EQ(runs[1].job_name, "killed mid-run");
    EXPECT_EQ(runs[1].outcome, "interrupted");
    EXPECT_GT(runs[1].ended_ms, 0);
    EXPECT_EQ(runs[1].alarms, 1) << "the alarm written before the kill was lost";
    EXPECT_EQ(runs[2].outcome, ""); // still running
    EXPECT_EQ(reader.integrityCheck(), "ok");
    fs::remove_all(dir);
}

TEST(RunRecord, ANewerSchemaAndAFileThatIsNoDatabaseAreRefusedByName) {
    const fs::path dir = freshDir("refused");
    const std::string db = (dir / "p.db").string();
    {
        sqlite3* raw = nullptr;
        ASSERT_EQ(sqlite3_open(db.c_str(), &raw), SQLITE_OK);
        ASSERT_EQ(sqlite3_exec(raw, "PRAGMA user_version = 99;", nullptr, nullptr, nullptr),
                  SQLITE_OK);
        sqlite3_close(raw);
    }
    try {
        SqliteRunRecord r(db, "op");
        ADD_FAILURE() << "schema 99 opened";
    } catch (const RecordError& e) {
        EXPECT_NE(std::string(e.what()).find("newer CutCell"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(db), std::string::npos) << e.what();
    }
    const std::string text = (dir / "notes.txt").string();
    writeFileAtomically(text, "these are not the droids you are looking for\n");
    EXPECT_THROW(SqliteRunRecord(text, "op"), RecordError);
    fs::remove_all(dir);
}

// Each machine's shipped job run by the CLI leaves one row: its machine, "completed", and what
// it made as its own summary.json says.
TEST(RunRecord, ARunOfEveryMachineLeavesItsRowWithTheFiguresOfItsRunLog) {
    const fs::path dir = freshDir("machines");
    const std::string db = (dir / "p.db").string();
    const std::string cli = CUTCELL_CLI;
    const char* jobs[] = {"default_job", "profile_cutter_job", "section_steel_job",
                          "flying_saw_job", "quick_return_job"};
    for (const char* job : jobs) {
        const std::string cmd = cli + " run " + CUTCELL_SOURCE_DIR + "/resources/jobs/" + job +
                                ".json --quiet --runs " + (dir / "runs").string() + " --record " +
                                db + " --report " + (dir / "report.json").string() + " 2>/dev/null";
        ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    }
    const SqliteRunRecord r(db, "");
    const auto runs = r.runs({});
    ASSERT_EQ(runs.size(), std::size(jobs));
    std::set<std::string> machines;
    for (const RecordedRun& run : runs) {
        SCOPED_TRACE(run.job_name);
        machines.insert(run.machine);
        EXPECT_EQ(run.outcome, "completed");
        const json::Value summary =
            json::parse(readTextFile((fs::path(run.run_dir) / "summary.json").string()));
        EXPECT_EQ(json::write(*summary.find("made"), 0), run.made_json);
        EXPECT_DOUBLE_EQ(summary.find("elapsed_s")->asNumber(), run.cycle_time_s);
        EXPECT_GT(run.cycle_time_s, 1.0);
        EXPECT_EQ(readTextFile((fs::path(run.run_dir) / "job.json").string()), r.jobTextOf(run.id));
    }
    EXPECT_EQ(machines.size(), std::size(jobs)) << "one row per machine";
    EXPECT_EQ(r.integrityCheck(), "ok");
    fs::remove_all(dir);
}

} // namespace
} // namespace cutcell
