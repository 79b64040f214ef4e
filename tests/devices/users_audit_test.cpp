// The station's users and audit trail against a real database - SQLite files, and a PostgreSQL
// server the test starts (record_backend.h: the same tests built twice) - (issue 25's security
// tests):
// the stored hash is Argon2id and verifies with libsodium's own crypto_pwhash_str_verify; wrong
// passwords lock a user out for a minute after five; short passwords, a first user who is no
// administrator and the last administrator's removal are refused by name; the trail shows every
// change and log-in made here, refuses edits and deletes in the database itself, and rolls its
// oldest records into an archive file without losing one; a record of schema 1 (written by the
// code before users existed, tests/data/record/) migrates and keeps its runs.
#include "core/job/job_io.h"
#include "core/json/json.h"
#include "devices/record/audit_trail.h"
#include "devices/record/run_record_store.h"
#include "devices/record/user_directory.h"
#include "tests/devices/record_backend.h"

#include <gtest/gtest.h>
#include <sodium.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

namespace cutcell {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> eventsNamed(const AuditTrail& trail, const std::string& event) {
    std::vector<std::string> keys;
    for (const RecordedAuditEvent& e : trail.events())
        if (e.event.event == event) keys.push_back(e.event.key);
    return keys;
}

TEST(Users, TheStoredHashIsArgon2idAndVerifiesWithLibsodium) {
    const std::string db = test::freshRecord("hash");
    AuditTrail trail(db);
    UserDirectory users(db, trail);
    ASSERT_TRUE(users.addUser("ada", UserLevel::Administrator, "correct horse", "root").ok());
    const std::string hash = users.storedHash("ada");
    EXPECT_EQ(hash.rfind("$argon2id$", 0), 0u) << hash;
    ASSERT_GE(sodium_init(), 0);
    EXPECT_EQ(crypto_pwhash_str_verify(hash.c_str(), "correct horse", 13), 0);
    EXPECT_NE(crypto_pwhash_str_verify(hash.c_str(), "correct horsE", 13), 0);
    // The password itself is nowhere in the record.
    const std::string bytes = test::recordBytes(db);
    EXPECT_NE(bytes.find("$argon2id$"), std::string::npos); // what is read holds the hash
    EXPECT_EQ(bytes.find("correct horse"), std::string::npos);
    const LoginResult ok = users.login("ada", "correct horse");
    EXPECT_TRUE(ok.outcome.ok()) << ok.outcome.message;
    EXPECT_EQ(ok.level, UserLevel::Administrator);
}

TEST(Users, FiveWrongPasswordsLockTheUserOutForAMinute) {
    const std::string db = test::freshRecord("lockout");
    std::int64_t now = 1'800'000'000'000;
    AuditTrail trail(db);
    UserDirectory users(db, trail, [&now] { return now; });
    ASSERT_TRUE(users.addUser("boss", UserLevel::Administrator, "long enough 1", "root").ok());
    ASSERT_TRUE(users.addUser("olga", UserLevel::Operator, "long enough 2", "boss").ok());
    for (int i = 1; i <= 4; ++i) {
        const LoginResult r = users.login("olga", "guess " + std::to_string(i));
        EXPECT_TRUE(r.outcome.refused());
        EXPECT_EQ(r.outcome.message, "user name or password wrong");
    }
    const LoginResult fifth = users.login("olga", "guess 5");
    EXPECT_NE(fifth.outcome.message.find("locked out for 60 s"), std::string::npos)
        << fifth.outcome.message;
    // Locked: even the right password is refused, with the time left.
    now += 20'000;
    const LoginResult locked = users.login("olga", "long enough 2");
    EXPECT_TRUE(locked.outcome.refused());
    EXPECT_NE(locked.outcome.message.find("locked out for 40 s more"), std::string::npos)
        << locked.outcome.message;
    // Another user is not affected; an unknown name says no more than a wrong password.
    EXPECT_TRUE(users.login("boss", "long enough 1").outcome.ok());
    EXPECT_EQ(users.login("nobody", "whatever1").outcome.message, "user name or password wrong");
    now += 40'001;
    EXPECT_TRUE(users.login("olga", "long enough 2").outcome.ok());
    EXPECT_EQ(eventsNamed(trail, audit_event::kLoginFailed).size(), 4u + 1 + 1);
    EXPECT_EQ(eventsNamed(trail, audit_event::kLockedOut), std::vector<std::string>{"olga"});
    EXPECT_EQ(eventsNamed(trail, audit_event::kLogin), (std::vector<std::string>{"boss", "olga"}));
}

TEST(Users, WeakPasswordsBadNamesAndALevelessStationAreRefusedByName) {
    const std::string db = test::freshRecord("refusals");
    AuditTrail trail(db);
    UserDirectory users(db, trail);
    const Outcome first = users.addUser("olga", UserLevel::Operator, "long enough", "root");
    EXPECT_TRUE(first.refused());
    EXPECT_NE(first.message.find("first user must be an administrator"), std::string::npos);
    const Outcome shortPw = users.addUser("ada", UserLevel::Administrator, "1234567", "root");
    EXPECT_EQ(shortPw.key, "password");
    EXPECT_NE(shortPw.message.find("7 characters; it needs at least 8"), std::string::npos)
        << shortPw.message;
    EXPECT_EQ(users.addUser("a b", UserLevel::Administrator, "long enough", "root").key, "user");
    ASSERT_TRUE(users.addUser("ada", UserLevel::Administrator, "long enough", "root").ok());
    EXPECT_NE(users.addUser("ada", UserLevel::Setter, "long enough", "ada").message.find("exists"),
              std::string::npos);
    const Outcome last = users.removeUser("ada", "ada");
    EXPECT_NE(last.message.find("last administrator"), std::string::npos) << last.message;
    EXPECT_TRUE(users.setLevel("ada", UserLevel::Engineer, "ada").refused());
    EXPECT_TRUE(users.users().size() == 1 && users.hasAdministrator());
}

TEST(AuditTrail, ShowsEveryChangeMadeAndTheFileRefusesEditsAndDeletes) {
    const std::string db = test::freshRecord("trail");
    {
        AuditTrail trail(db);
        UserDirectory users(db, trail);
        ASSERT_TRUE(users.addUser("ada", UserLevel::Administrator, "long enough", "root").ok());
        ASSERT_TRUE(users.addUser("sam", UserLevel::Setter, "long enough", "ada").ok());
        ASSERT_TRUE(users.setLevel("sam", UserLevel::Engineer, "ada").ok());
        ASSERT_TRUE(users.setPassword("sam", "another one", "ada").ok());
        trail.append(
            {0, "sam", audit_event::kParameterChanged, "controller.kp", "120", "140", "1/s", ""});
        trail.append({0, "sam", audit_event::kEmergencyStop, "", "", "", "", "operator column"});
        ASSERT_TRUE(users.removeUser("sam", "ada").ok());
        users.logout("ada");
    }
    AuditTrail again(db); // the trail is in the file, not in memory
    const auto events = again.events();
    std::vector<std::string> seen;
    for (const auto& e : events)
        seen.push_back(e.event.event + " " + e.event.key);
    const std::vector<std::string> expected = {"user added ada",
                                               "user added sam",
                                               "level changed sam",
                                               "password changed sam",
                                               "parameter changed controller.kp",
                                               "emergency stop ",
                                               "user removed sam",
                                               "logout ada"};
    EXPECT_EQ(seen, expected);
    EXPECT_EQ(events[2].event.old_value, "setter");
    EXPECT_EQ(events[2].event.new_value, "engineer");
    EXPECT_EQ(events[4].event.unit, "1/s");
    for (const auto& e : events)
        EXPECT_GT(e.event.unix_ms, 1'700'000'000'000) << e.event.event;
    // Append-only in the database itself: another program's UPDATE or DELETE is refused.
    std::string why;
    EXPECT_FALSE(test::execOnRecord(db, "UPDATE audit SET actor = 'x'", &why));
    EXPECT_NE(why.find("append-only"), std::string::npos) << why;
    EXPECT_FALSE(test::execOnRecord(db, "DELETE FROM audit", &why));
    EXPECT_NE(why.find("append-only"), std::string::npos) << why;
    EXPECT_EQ(again.count(), static_cast<std::int64_t>(expected.size()));
}

TEST(AuditTrail, PastItsBoundTheOldestRecordsGoToAnArchiveNoneIsLost) {
    const std::string db = test::freshRecord("roll");
    AuditTrail trail(db, 50);
    const int appended = 237;
    for (int i = 0; i < appended; ++i)
        trail.append({0, "sam", audit_event::kOverrideChanged, "override", std::to_string(i),
                      std::to_string(i + 1), "%", ""});
    EXPECT_LE(trail.count(), 50);
    // Every record is either still in the table or in exactly one archive line.
    std::set<std::string> values;
    int archived = 0;
    for (const auto& e : trail.events())
        if (e.event.event == audit_event::kOverrideChanged) values.insert(e.event.old_value);
    for (const auto& f : fs::directory_iterator(trail.archiveDir())) {
        std::ifstream in(f.path());
        for (std::string line; std::getline(in, line);) {
            const json::Value v = json::parse(line);
            if (v.find("event")->asString() != audit_event::kOverrideChanged) continue;
            EXPECT_TRUE(values.insert(v.find("old")->asString()).second) << "twice: " << line;
            ++archived;
        }
    }
    EXPECT_EQ(values.size(), static_cast<size_t>(appended));
    EXPECT_GT(archived, 0);
    // Each roll is itself an event naming its file.
    const auto rolls = eventsNamed(trail, audit_event::kArchived);
    EXPECT_FALSE(rolls.empty());
}

TEST(ProductionDb, ARecordOfSchema1MigratesAndKeepsItsRuns) {
    const std::string db = test::schema1Record("migrate");
    EXPECT_EQ(test::schemaVersionOf(db), 1); // the record really is of the old schema
    RunRecordStore record(db, "op");
    EXPECT_EQ(record.schemaVersion(), kProductionDbSchema);
    const auto runs = record.runs({});
    ASSERT_EQ(runs.size(), 2u);
    std::set<std::string> machines;
    for (const auto& r : runs) {
        machines.insert(r.machine);
        EXPECT_EQ(r.outcome, "completed");
        EXPECT_FALSE(record.jobTextOf(r.id).empty());
    }
    EXPECT_EQ(machines, (std::set<std::string>{"quick_return_cutter", "flying_saw"}));
    AuditTrail trail(db);
    UserDirectory users(db, trail);
    EXPECT_TRUE(users.addUser("ada", UserLevel::Administrator, "long enough", "root").ok());
    EXPECT_EQ(record.integrityCheck(), "ok");
}

// Runs `cutcell-cli ARGS` with `input` on its standard input; returns the exit code, stdout in
// *out (stderr goes with it).
int cli(const std::string& args, const std::string& input, std::string* out) {
    const fs::path in =
        fs::temp_directory_path() / ("cutcell_users_in_" + std::to_string(getpid()));
    writeFileAtomically(in.string(), input);
    const std::string cmd = std::string(CUTCELL_CLI) + " " + args + " < " + in.string() + " 2>&1";
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) return -1;
    char buf[4096];
    out->clear();
    for (size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;)
        out->append(buf, n);
    const int status = pclose(p);
    fs::remove(in);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The CLI as an administrator uses it: the first administrator without a log-in, then every
// change authorised by an administrator's password; a wrong one changes nothing; the audit
// trail lists it all, as CSV too.
TEST(UsersCli, AddsAUserOnlyWithAnAdministratorsPasswordAndTheTrailListsIt) {
    const std::string db = "--db " + test::freshRecord("cli");
    std::string out;
    EXPECT_EQ(cli("users list " + db, "", &out), 0);
    EXPECT_NE(out.find("single-user mode"), std::string::npos) << out;
    EXPECT_EQ(cli("users add olga --level operator " + db, "long enough\n", &out), 1);
    EXPECT_NE(out.find("first user must be an administrator"), std::string::npos) << out;
    EXPECT_EQ(cli("users add ada --level administrator " + db, "long enough\n", &out), 0) << out;
    EXPECT_EQ(cli("users add olga --level operator " + db, "olga's pass\n", &out), 1);
    EXPECT_NE(out.find("--admin NAME"), std::string::npos) << out;
    EXPECT_EQ(
        cli("users add olga --level operator --admin ada " + db, "wrong one\nolga pass\n", &out),
        1);
    EXPECT_NE(out.find("user name or password wrong"), std::string::npos) << out;
    EXPECT_EQ(cli("users add olga --level boss --admin ada " + db, "", &out), 64);
    EXPECT_NE(out.find("operator, setter, engineer or administrator"), std::string::npos) << out;
    EXPECT_EQ(
        cli("users add olga --level operator --admin ada " + db, "long enough\nolga pass\n", &out),
        0)
        << out;
    EXPECT_EQ(cli("users list " + db, "", &out), 0);
    EXPECT_NE(out.find("olga"), std::string::npos);
    EXPECT_NE(out.find("operator"), std::string::npos);
    EXPECT_EQ(cli("audit --csv " + db, "", &out), 0);
    EXPECT_EQ(out.rfind("id,time,actor,event,key,old,new,unit,detail\n", 0), 0u) << out;
    EXPECT_NE(out.find(",ada,user added,olga,,operator,"), std::string::npos) << out;
    EXPECT_NE(out.find(",ada,login failed,ada,"), std::string::npos) << out;
    EXPECT_EQ(cli("audit --since 2026-02-30 " + db, "", &out), 64);
}

} // namespace
} // namespace cutcell
