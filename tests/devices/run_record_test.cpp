// The production record against a real database - SQLite files, and a PostgreSQL server the
// test starts (record_backend.h: the same tests built twice): the schema from an empty record,
// a run of every machine through `cutcell-cli run --record` with the figures of its own
// summary.json, a program killed during a run (closed as interrupted at the next start,
// nothing else lost, the integrity check ok), a live program's run left open, and a newer
// schema refused.
#include "core/job/job_io.h"
#include "core/json/json.h"
#include "devices/record/run_record_store.h"
#include "tests/devices/record_backend.h"

#include <gtest/gtest.h>
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

using test::freshRecord;

TEST(RunRecord, AnEmptyRecordGetsTheSchemaAndARunRoundTrips) {
    const std::string db = freshRecord("roundtrip");
    {
        RunRecordStore r(db, "ada");
        EXPECT_EQ(r.schemaVersion(), RunRecordStore::kSchemaVersion);
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
        EXPECT_EQ(runs[0].job_hash, RunRecordStore::jobFingerprint(job));
        EXPECT_NE(runs[0].job_hash, RunRecordStore::jobFingerprint(job + " "));
        // Filters.
        RunQuery byMachine, bySince, byOutcome;
        byMachine.machine = "pipe_robot_6axis";
        bySince.since_ms = 1'000'001;
        byOutcome.outcome = "fault: axis 1";
        EXPECT_EQ(r.runs(byMachine).size(), 0u);
        EXPECT_EQ(r.runs(bySince).size(), 0u);
        EXPECT_EQ(r.runs(byOutcome).size(), 1u);
    }
    RunRecordStore again(db, "ada"); // reopening migrates nothing and keeps the run
    EXPECT_EQ(again.runs({}).size(), 1u);
    EXPECT_EQ(again.integrityCheck(), "ok");
}

TEST(RunRecord, AKilledProgramsRunIsClosedAsInterruptedAndALiveOnesStaysOpen) {
    const std::string db = freshRecord("killed");
    {
        RunRecordStore r(db, "op");
        r.opened({1, "done", "{}", "", 1000});
        r.closed({"completed", 2000, "{}"});
    }
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        RunRecordStore r(db, "op");
        r.opened({2, "killed mid-run", "{}", "", 3000});
        r.alarm({3100, "warning", "a note before the kill"});
        raise(SIGKILL);
        _exit(0);
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);

    RunRecordStore live(db, "op"); // this process: its own open run must survive a reader
    EXPECT_EQ(live.interruptedAtOpen(), 1);
    live.opened({3, "running here", "{}", "", 4000});
    const RunRecordStore reader(db, "");
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
}

TEST(RunRecord, ANewerSchemaAndARecordThatIsNoneAreRefusedByName) {
    const std::string db = freshRecord("refused");
    test::markSchemaVersion(db, 99);
    try {
        RunRecordStore r(db, "op");
        ADD_FAILURE() << "schema 99 opened";
    } catch (const RecordError& e) {
        EXPECT_NE(std::string(e.what()).find("newer CutCell"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(db), std::string::npos) << e.what();
    }
    const std::string none = test::notARecord("none");
    try {
        RunRecordStore r(none, "op");
        ADD_FAILURE() << none << " opened";
    } catch (const RecordError& e) {
        EXPECT_NE(std::string(e.what()).find(none), std::string::npos) << e.what();
    }
}

// Each machine's shipped job run by the CLI leaves one row: its machine, "completed", and what
// it made as its own summary.json says.
TEST(RunRecord, ARunOfEveryMachineLeavesItsRowWithTheFiguresOfItsRunLog) {
    const fs::path dir = freshDir("machines"); // the run folders
    const std::string db = freshRecord("machines");
    const std::string cli = CUTCELL_CLI;
    const char* jobs[] = {"default_job", "profile_cutter_job", "section_steel_job",
                          "flying_saw_job", "quick_return_job"};
    for (const char* job : jobs) {
        const std::string cmd = cli + " run " + CUTCELL_SOURCE_DIR + "/resources/jobs/" + job +
                                ".json --quiet --runs " + (dir / "runs").string() + " --record " +
                                db + " --report " + (dir / "report.json").string() + " 2>/dev/null";
        ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    }
    const RunRecordStore r(db, "");
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

namespace cutcell {
namespace {

// A PostgreSQL connection string may hold a password: it is recognised in every libpq form
// (not taken for a file name) and never shown, even when libpq cannot read the string.
TEST(RunRecord, APasswordInAConnectionStringIsNeverShown) {
    EXPECT_TRUE(isPostgresConnection("postgresql://u:pw@db/cells"));
    EXPECT_TRUE(isPostgresConnection("  password=s3cret-word host=127.0.0.1 dbname=x"));
    EXPECT_TRUE(isPostgresConnection("sslmode=require host=db"));
    EXPECT_FALSE(isPostgresConnection("/home/op/production.db"));
    EXPECT_FALSE(isPostgresConnection("cell=3.db")); // no libpq keyword: a file's name
    for (const std::string& where :
         {std::string("password=s3cret-word host=127.0.0.1 port=1 dbname=x connect_timeout=2"),
          std::string("postgresql://u:s3cret-word@127.0.0.1:1/x?connect_timeout=2"),
          std::string("postgresql://u:s3cret-word%zz@[::1/x")}) {
        try {
            RunRecordStore r(where, "op");
            ADD_FAILURE() << "opened " << where;
        } catch (const RecordError& e) {
            EXPECT_EQ(std::string(e.what()).find("s3cret"), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("postgresql://"), std::string::npos) << e.what();
        }
    }
}

} // namespace
} // namespace cutcell
