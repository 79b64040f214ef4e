// The consumable ledger (issue 24) against a real database - SQLite files, and a PostgreSQL
// server the test starts (record_backend.h: the same tests built twice): counts add up and
// survive reopening, each station and set counts its own, a replacement starts from zero, keeps
// the old set as history and is in the audit trail, bad figures are refused; the wear levels at
// 89.9 / 90 / 100 % and an unknown life that never warns; and the acceptance test: a writer
// killed with SIGKILL at random moments loses no cut beyond the one it was committing.
#include "core/job/job_io.h"
#include "core/json/json.h"
#include "core/process/consumable_counters.h"
#include "devices/record/audit_trail.h"
#include "devices/record/consumable_ledger_store.h"
#include "tests/devices/record_backend.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>

namespace cutcell {
namespace {

constexpr std::int64_t kT0 = 1'780'000'000'000; // a fixed clock: installation times are exact

const ConsumableSetId kSet{CutProcess::Plasma, "Powermax65/85 45A shielded"};

struct NoAudit final : AuditSink {
    void append(const AuditEvent&) override {}
};

TEST(ConsumableLedger, CountsAddUpPerStationAndSetAndSurviveReopening) {
    const std::string db = test::freshRecord("consumable_counts");
    NoAudit audit;
    {
        ConsumableLedgerStore ledger(db, audit, "cell-1", [] { return kT0; });
        EXPECT_EQ(ledger.current(kSet).id, 0) << "no cut yet: nothing installed";
        EXPECT_EQ(ledger.current(kSet).pierces, 0);
        ledger.recordCut(kSet, 1, 12.5, 300.0);
        ledger.recordCut(kSet, 2, 0.25, 50.5);
        const ConsumableCounters c = ledger.recordCut(kSet, 0, 1.0005, 0.0); // an edge start
        EXPECT_EQ(c.cuts, 3);
        EXPECT_EQ(c.pierces, 3);
        EXPECT_EQ(c.arc_on_ms, 12'500 + 250 + 1'001);
        EXPECT_DOUBLE_EQ(c.cut_length_mm, 350.5);
        EXPECT_EQ(c.installed_ms, kT0); // installed by its first cut
        EXPECT_EQ(c.removed_ms, 0);
        // Another station on the same record, another process with the same name: their own.
        ConsumableLedgerStore other(db, audit, "cell-2", [] { return kT0; });
        other.recordCut(kSet, 5, 1.0, 1.0);
        ledger.recordCut({CutProcess::OxyFuel, kSet.consumable}, 7, 1.0, 1.0);
        EXPECT_EQ(other.current(kSet).pierces, 5);
        EXPECT_EQ(other.totals().pierces, 5);
    }
    const ConsumableLedgerStore again(db, audit, "cell-1");
    const ConsumableCounters c = again.current(kSet);
    EXPECT_EQ(c.cuts, 3);
    EXPECT_EQ(c.pierces, 3);
    EXPECT_EQ(c.arc_on_ms, 13'751);
    EXPECT_DOUBLE_EQ(c.cut_length_mm, 350.5);
    EXPECT_EQ(c.set, kSet);
    const ConsumableTotals t = again.totals();
    EXPECT_EQ(t.sets, 2);
    EXPECT_EQ(t.cuts, 4);
    EXPECT_EQ(t.pierces, 10);
    EXPECT_EQ(t.arc_on_ms, 14'751);
    EXPECT_DOUBLE_EQ(t.cut_length_mm, 351.5);
    EXPECT_EQ(openRecordDb(db)->integrityCheck().rfind("ok", 0), 0u);
}

TEST(ConsumableLedger, AReplacementStartsFromZeroKeepsTheOldSetAndIsAudited) {
    const std::string db = test::freshRecord("consumable_replace");
    AuditTrail trail(db);
    std::int64_t now = kT0;
    ConsumableLedgerStore ledger(db, trail, "cell-1", [&] { return now; });
    ledger.recordCut(kSet, 1, 10.0, 100.0);
    ledger.recordCut(kSet, 1, 20.0, 200.0);
    now += 3'600'000;
    const ConsumableCounters fitted = ledger.replace(kSet, "olga", "nozzle worn, arc wanders");
    EXPECT_EQ(fitted.cuts, 0);
    EXPECT_EQ(fitted.pierces, 0);
    EXPECT_EQ(fitted.installed_ms, now);
    EXPECT_EQ(ledger.current(kSet).id, fitted.id);
    EXPECT_EQ(ledger.current(kSet).pierces, 0);
    now += 1000;
    EXPECT_EQ(ledger.recordCut(kSet, 1, 5.0, 50.0).pierces, 1); // counted on the new set only

    const std::vector<ConsumableCounters> h = ledger.history(kSet);
    ASSERT_EQ(h.size(), 2u);
    EXPECT_EQ(h[0].pierces, 2);
    EXPECT_EQ(h[0].arc_on_ms, 30'000);
    EXPECT_EQ(h[0].installed_ms, kT0);
    EXPECT_EQ(h[0].removed_ms, kT0 + 3'600'000);
    EXPECT_EQ(h[0].removed_by, "olga");
    EXPECT_EQ(h[0].removal_reason, "nozzle worn, arc wanders");
    EXPECT_EQ(h[1].id, fitted.id);
    EXPECT_EQ(h[1].removed_ms, 0);
    EXPECT_EQ(h[1].pierces, 1);
    EXPECT_EQ(ledger.totals().pierces, 3); // history counts in the totals
    EXPECT_EQ(ledger.totals().sets, 2);

    // The trail names who, which set, the counts at the replacement and why.
    int found = 0;
    for (const RecordedAuditEvent& r : trail.events()) {
        if (r.event.event != kConsumablesReplacedEvent) continue;
        ++found;
        EXPECT_EQ(r.event.actor, "olga");
        EXPECT_EQ(r.event.key, "plasma / Powermax65/85 45A shielded");
        EXPECT_EQ(r.event.old_value, "2 pierces, 30.000 s arc-on, 300.0 mm cut, 2 cuts");
        EXPECT_EQ(r.event.new_value, "0 pierces, 0.000 s arc-on, 0.0 mm cut, 0 cuts");
        EXPECT_NE(r.event.detail.find("nozzle worn, arc wanders"), std::string::npos)
            << r.event.detail;
        EXPECT_NE(r.event.detail.find("cell-1"), std::string::npos) << r.event.detail;
        EXPECT_EQ(r.event.unix_ms, kT0 + 3'600'000);
    }
    EXPECT_EQ(found, 1);

    // A set replaced before its first cut: a row of zeros closed, the event says so.
    ledger.replace({CutProcess::Laser, "nozzle 1.5"}, "olga", "");
    EXPECT_EQ(ledger.history({CutProcess::Laser, "nozzle 1.5"}).size(), 1u);
    EXPECT_EQ(trail.events().back().event.old_value, "none recorded");
    EXPECT_NE(trail.events().back().event.detail.find("(none given)"), std::string::npos);

    // The database itself holds one set in the torch per station, process and consumable.
    std::string why;
    EXPECT_FALSE(test::execOnRecord(db,
                                    "INSERT INTO consumable_sets (station, process, consumable, "
                                    "installed_ms) VALUES ('cell-1', 'plasma', "
                                    "'Powermax65/85 45A shielded', 1)",
                                    &why));
    EXPECT_FALSE(why.empty());
}

TEST(ConsumableLedger, FiguresNoCutHasAndNamelessReplacementsAreRefused) {
    const std::string db = test::freshRecord("consumable_refused");
    NoAudit audit;
    ConsumableLedgerStore ledger(db, audit, "cell-1");
    EXPECT_THROW(ledger.recordCut(kSet, -1, 1.0, 1.0), std::invalid_argument);
    EXPECT_THROW(ledger.recordCut(kSet, 1, std::numeric_limits<double>::quiet_NaN(), 1.0),
                 std::invalid_argument);
    EXPECT_THROW(ledger.recordCut(kSet, 1, 1.0, -0.5), std::invalid_argument);
    EXPECT_THROW(ledger.recordCut({CutProcess::Plasma, ""}, 1, 1.0, 1.0), std::invalid_argument);
    EXPECT_THROW(ledger.replace(kSet, "", "worn"), std::invalid_argument);
    EXPECT_EQ(ledger.current(kSet).cuts, 0) << "a refused cut was counted";
}

ConsumableCounters used(std::int64_t pierces, std::int64_t arcMs) {
    ConsumableCounters c;
    c.pierces = pierces;
    c.arc_on_ms = arcMs;
    return c;
}

TEST(ConsumableWear, WarnsAt90AndAlarmsAt100PercentOfTheLimitUsedMost) {
    const ConsumableLife pierces{1000, 0};
    EXPECT_EQ(consumableWear(used(899, 0), pierces).level, WearLevel::Ok);
    EXPECT_EQ(consumableWear(used(899, 0), pierces).text, "pierces: 899 of 1000 (89.9 %)");
    EXPECT_EQ(consumableWear(used(900, 0), pierces).level, WearLevel::Warning);
    EXPECT_EQ(consumableWear(used(900, 0), pierces).text, "pierces: 900 of 1000 (90 %)");
    EXPECT_EQ(consumableWear(used(999, 0), pierces).level, WearLevel::Warning);
    EXPECT_EQ(consumableWear(used(1000, 0), pierces).level, WearLevel::Alarm);
    EXPECT_EQ(consumableWear(used(1500, 0), pierces).level, WearLevel::Alarm);
    EXPECT_DOUBLE_EQ(consumableWear(used(1500, 0), pierces).fraction, 1.5);

    // Arc-on time from a chart's minutes: 50 min = 3000 s; 2697 s is 89.9 %.
    CutChart chart;
    chart.life_arc_minutes = 50.0;
    const ConsumableLife arc = consumableLifeOf(chart);
    EXPECT_EQ(arc.pierces, 0);
    EXPECT_DOUBLE_EQ(arc.arc_s, 3000.0);
    EXPECT_EQ(consumableWear(used(0, 2'697'000), arc).level, WearLevel::Ok);
    EXPECT_EQ(consumableWear(used(0, 2'699'999), arc).level, WearLevel::Ok); // 1 ms short
    EXPECT_EQ(consumableWear(used(0, 2'700'000), arc).level, WearLevel::Warning);
    EXPECT_EQ(consumableWear(used(0, 2'700'000), arc).text, "arc-on time: 45.0 of 50.0 min (90 %)");
    EXPECT_EQ(consumableWear(used(0, 3'000'000), arc).level, WearLevel::Alarm);

    // Both known: the larger fraction is named, the level is the worse.
    chart.life_pierces = 1000;
    const ConsumableLife both = consumableLifeOf(chart);
    const ConsumableWear w = consumableWear(used(500, 2'850'000), both);
    EXPECT_EQ(w.level, WearLevel::Warning);
    EXPECT_EQ(w.limit, WearLimit::ArcTime);
    EXPECT_DOUBLE_EQ(w.fraction, 0.95);
    const ConsumableWear p = consumableWear(used(1000, 2'850'000), both);
    EXPECT_EQ(p.level, WearLevel::Alarm);
    EXPECT_EQ(p.limit, WearLimit::Pierces);
    EXPECT_STREQ(toString(p.level), "alarm");
}

TEST(ConsumableWear, AnUnknownLifeNeverWarns) {
    const CutChart chart; // the shipped charts give no life yet
    const ConsumableLife none = consumableLifeOf(chart);
    EXPECT_EQ(none.pierces, 0);
    EXPECT_EQ(none.arc_s, 0.0);
    const ConsumableWear w = consumableWear(used(1'000'000, 3'600'000'000), none);
    EXPECT_EQ(w.level, WearLevel::Ok);
    EXPECT_EQ(w.limit, WearLimit::None);
    EXPECT_EQ(w.fraction, 0.0);
    EXPECT_EQ(w.text, "expected life unknown");
    // One limit known: only it counts.
    EXPECT_EQ(consumableWear(used(1'000'000, 1000), {0, 100.0}).level, WearLevel::Ok);
    EXPECT_EQ(consumableWear(used(1'000'000, 1000), {0, 100.0}).limit, WearLimit::ArcTime);
}

// The kill test's writer (consumable_writer_main.cpp): $CUTCELL_CONSUMABLE_WRITER, else the
// one the build names; "" when neither does.
std::string writerPath() {
    if (const char* e = std::getenv("CUTCELL_CONSUMABLE_WRITER"); e && *e) return e;
#ifdef CUTCELL_CONSUMABLE_WRITER
    return CUTCELL_CONSUMABLE_WRITER;
#else
    return "";
#endif
}

// The writer's lines so far (whole lines only) and whether its output has ended.
struct WriterOutput {
    std::string pending;
    std::int64_t last = -1; // the last count printed (-1: none yet)
    int lines = 0;
    bool read(int fd) {
        char buf[4096];
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n < 0 && errno == EINTR) return true;
        if (n <= 0) return false;
        pending.append(buf, static_cast<std::size_t>(n));
        for (std::size_t nl; (nl = pending.find('\n')) != std::string::npos;) {
            last = std::stoll(pending.substr(0, nl));
            ++lines;
            pending.erase(0, nl + 1);
        }
        return true;
    }
};

// The acceptance test: a writer killed with SIGKILL at a random moment - before its first
// commit, between two, during one, between a commit and its line - loses no cut it printed and
// counts none twice. It prints a count only after the commit returned, so the record holds at
// least the last count printed; a kill after a commit but before its line leaves one more, never
// two (the next cut's transaction had not begun). Each round reopens the record and goes on
// counting: the counts also survive the restarts.
TEST(ConsumableLedger, AWriterKilledAtARandomMomentLosesNoCompletedCut) {
    const std::string writer = writerPath();
    if (writer.empty()) GTEST_SKIP() << "no consumable_writer (set CUTCELL_CONSUMABLE_WRITER)";
    const std::string db = test::freshRecord("consumable_kill");
    const ConsumableSetId set{CutProcess::Plasma, "kill test set"}; // the writer's
    const unsigned seed = std::random_device{}();
    SCOPED_TRACE("seed " + std::to_string(seed) + ", " + test::recordBackendName());
    std::mt19937 random(seed);
    std::int64_t stored = 0; // the count the record held after the last round
    for (int round = 0; round < 8; ++round) {
        // Kill after this many lines (0: perhaps before the first commit, even while the record
        // is being created), then after up to 3 ms more.
        const int lines = std::uniform_int_distribution<int>(0, 30)(random);
        const int extraUs = std::uniform_int_distribution<int>(0, 3000)(random);
        int out[2];
        ASSERT_EQ(pipe(out), 0);
        const pid_t child = fork();
        ASSERT_GE(child, 0);
        if (child == 0) {
            dup2(out[1], STDOUT_FILENO);
            close(out[0]);
            close(out[1]);
            execl(writer.c_str(), writer.c_str(), db.c_str(), static_cast<char*>(nullptr));
            _exit(127);
        }
        close(out[1]);
        WriterOutput printed;
        bool open = true;
        while (open && printed.lines < lines)
            open = printed.read(out[0]);
        std::this_thread::sleep_for(std::chrono::microseconds(extraUs));
        kill(child, SIGKILL);
        int status = 0;
        ASSERT_EQ(waitpid(child, &status, 0), child);
        while (printed.read(out[0])) { // what it printed before it died
        }
        close(out[0]);
        ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL)
            << "round " << round << ": the writer ended by itself (status " << status << ")";
        const std::int64_t last = printed.last < 0 ? stored : printed.last;

        NoAudit audit;
        const ConsumableLedgerStore ledger(db, audit, "kill-test");
        const ConsumableCounters c = ledger.current(set);
        SCOPED_TRACE("round " + std::to_string(round) + ": killed after " +
                     std::to_string(printed.lines) + " lines + " + std::to_string(extraUs) + " us");
        EXPECT_GE(c.cuts, last) << "a cut the writer had reported committed was lost";
        EXPECT_LE(c.cuts, last + 1) << "more cuts than the writer made";
        // Each cut's figures went in with it (one transaction), never in part.
        EXPECT_EQ(c.pierces, c.cuts);
        EXPECT_EQ(c.arc_on_ms, 500 * c.cuts);
        EXPECT_DOUBLE_EQ(c.cut_length_mm, 10.0 * static_cast<double>(c.cuts));
        EXPECT_EQ(openRecordDb(db)->integrityCheck().rfind("ok", 0), 0u);
        stored = c.cuts;
    }
    EXPECT_GT(stored, 0) << "no round let the writer commit a cut";
}

} // namespace
} // namespace cutcell

#ifdef CUTCELL_CLI
namespace cutcell {
namespace {

// The whole path: cutcell-cli runs a plasma job on the simulated cell with this record; the
// engine tells the record at each cut's end, and the ledger counts it for the job's consumable
// set. Two runs, two cuts: pierces, arc-on time (the torch's time on: the cut and its pierce)
// and length from the run's own report.
TEST(ConsumableLedger, RunsOfAPlasmaJobCountTheirCutsInTheRecord) {
    const std::string db = test::freshRecord("consumable_runs");
    char tmpl[] = "/tmp/cutcell-consumable-run-XXXXXX";
    const std::string dir = ::mkdtemp(tmpl);
    json::Value job =
        json::parse(readTextFile(CUTCELL_SOURCE_DIR "/resources/jobs/plasma_hole_job.json"));
    json::Value engine = *job.find("engine");
    engine.set("runs_dir", ""); // no run log folder
    job.set("engine", engine);
    writeFileAtomically(dir + "/job.json", json::write(job));
    double cutTime = 0, length = 0;
    for (int run = 0; run < 2; ++run) {
        const std::string cmd = std::string(CUTCELL_CLI) + " run " + dir +
                                "/job.json --quiet --record '" + db + "' --report " + dir +
                                "/report.json >/dev/null 2>&1";
        ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
        const json::Value report = json::parse(readTextFile(dir + "/report.json"));
        cutTime = report.find("cut_time_s")->asNumber();
        length = report.find("length_mm")->asNumber();
    }
    NoAudit audit;
    const ConsumableLedgerStore ledger(db, audit); // this host's station, as the CLI's
    const ConsumableCounters c = ledger.current({CutProcess::Plasma, "Powermax65/85 65A shielded"});
    std::printf("two runs: %lld cuts, %lld pierces, arc-on %.3f s, %.3f mm (a cut: %.3f s, %.3f "
                "mm)\n",
                static_cast<long long>(c.cuts), static_cast<long long>(c.pierces), c.arcOnS(),
                c.cut_length_mm, cutTime, length);
    EXPECT_EQ(c.cuts, 2);
    EXPECT_EQ(c.pierces, 2);
    EXPECT_GE(c.arcOnS(), 2 * cutTime - 0.002);
    EXPECT_LE(c.arcOnS(), 2 * cutTime + 0.1); // the cut, its start on the path and the arc off
    EXPECT_NEAR(c.cut_length_mm, 2 * length, 1e-6);
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace cutcell
#endif
