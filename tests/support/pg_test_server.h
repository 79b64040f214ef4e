#pragma once
// A PostgreSQL server of a test's own (Debian postgresql): a fresh cluster in a temporary
// folder (initdb, trust authentication on 127.0.0.1 only, fsync off), started on a port the
// kernel chose and stopped with the test; each test makes its own database on it. PostgreSQL
// refuses to run as root: as root the cluster is run as the "postgres" user (runuser). Where
// no server can start (no binaries, no such user), start() says why and the test reports
// itself skipped.
#include "tests/support/free_local_port.h"

#include <libpq-fe.h>
#include <pwd.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace cutcell::test {

class PgTestServer {
  public:
    PgTestServer() = default;
    ~PgTestServer() { stop(); }
    PgTestServer(const PgTestServer&) = delete;
    PgTestServer& operator=(const PgTestServer&) = delete;

    // Starts the cluster; false with the reason in *why.
    bool start(std::string* why) {
        namespace fs = std::filesystem;
        const std::string bin = binDir();
        if (bin.empty()) return fail(why, "no PostgreSQL server (/usr/lib/postgresql/*/bin)");
        std::string as; // the command prefix running as the cluster's owner
        const passwd* owner = nullptr;
        if (geteuid() == 0) {
            owner = getpwnam("postgres");
            if (!owner) return fail(why, "running as root and no \"postgres\" user to run it");
            as = "runuser -u postgres -- ";
        }
        // The postgres user must reach the folder: /tmp itself when root hands it over (a
        // TMPDIR under /root would not do).
        const fs::path base = owner ? fs::path("/tmp") : fs::temp_directory_path();
        dir_ = base / ("cutcell_pg_" + std::to_string(getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        if (owner && chown(dir_.c_str(), owner->pw_uid, owner->pw_gid) != 0)
            return fail(why, "cannot hand " + dir_.string() + " to the postgres user");
        port_ = freeLocalPort();
        if (port_ == 0) return fail(why, "no free local port");
        const std::string data = (dir_ / "data").string(), log = (dir_ / "server.log").string();
        if (!run(as + bin + "/initdb -D " + data +
                 " -U cutcell -A trust -E UTF8 --locale=C --no-sync > " +
                 (dir_ / "initdb.log").string() + " 2>&1"))
            return fail(why, "initdb failed (" + tail((dir_ / "initdb.log").string()) + ")");
        const std::string options = "-p " + std::to_string(port_) + " -k " + dir_.string() +
                                    " -c listen_addresses=127.0.0.1 -c fsync=off"
                                    " -c full_page_writes=off -c synchronous_commit=off";
        const std::string ctl =
            as + bin + "/pg_ctl -D " + data + " -l " + log + " -w -t 60 -o '" + options + "' ";
        if (!run(ctl + "start > /dev/null 2>&1"))
            return fail(why, "the server did not start (" + tail(log) + ")");
        restartCommand_ = ctl + "-m fast restart > /dev/null 2>&1";
        stopCommand_ = as + bin + "/pg_ctl -D " + data + " -m immediate -w stop > /dev/null 2>&1";
        // A test killed (a crash, ctest's time-out) cannot stop its server: a watchdog does,
        // once this process is gone, and removes the folder.
        run("(while kill -0 " + std::to_string(getpid()) + " 2>/dev/null; do sleep 1; done; " +
            stopCommand_ + "; rm -rf " + dir_.string() + ") > /dev/null 2>&1 &");
        return true;
    }

    // Stops the server (every session ends) and starts it again on the same port.
    bool restart() { return !restartCommand_.empty() && run(restartCommand_); }

    void stop() {
        if (!stopCommand_.empty()) run(stopCommand_);
        stopCommand_.clear();
        if (!dir_.empty()) {
            std::error_code ec;
            std::filesystem::remove_all(dir_, ec);
            dir_.clear();
        }
    }

    // postgresql://cutcell@127.0.0.1:PORT/DB
    std::string uri(const std::string& db) const {
        return "postgresql://cutcell@127.0.0.1:" + std::to_string(port_) + "/" + db;
    }

    // A new empty database (with the amcheck extension, for the record's integrity check);
    // "" with the server's reason in *why.
    bool createDatabase(const std::string& db, std::string* why) {
        if (!exec(uri("postgres"), "CREATE DATABASE " + db, why)) return false;
        return exec(uri(db), "CREATE EXTENSION IF NOT EXISTS amcheck", why);
    }

    // Runs `sql` on its own connection; false with the server's reason in *why.
    static bool exec(const std::string& uri, const std::string& sql, std::string* why) {
        PGconn* c = PQconnectdb(uri.c_str());
        bool ok = PQstatus(c) == CONNECTION_OK;
        if (ok) {
            PGresult* r = PQexec(c, sql.c_str());
            const ExecStatusType s = PQresultStatus(r);
            ok = s == PGRES_COMMAND_OK || s == PGRES_TUPLES_OK;
            PQclear(r);
        }
        if (!ok && why) *why = PQerrorMessage(c);
        PQfinish(c);
        return ok;
    }

    int port() const { return port_; }

  private:
    static bool fail(std::string* why, const std::string& reason) {
        if (why) *why = reason;
        return false;
    }
    static bool run(const std::string& cmd) { return std::system(cmd.c_str()) == 0; }
    static std::string tail(const std::string& file) {
        std::string text;
        if (FILE* f = std::fopen(file.c_str(), "r")) {
            char buf[4096];
            for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;)
                text.append(buf, n);
            std::fclose(f);
        }
        if (text.size() > 400) text = text.substr(text.size() - 400);
        std::replace(text.begin(), text.end(), '\n', ' ');
        return text;
    }
    // The newest installed server's binaries.
    static std::string binDir() {
        namespace fs = std::filesystem;
        std::vector<std::string> found;
        std::error_code ec;
        for (const auto& e : fs::directory_iterator("/usr/lib/postgresql", ec))
            if (fs::exists(e.path() / "bin" / "initdb"))
                found.push_back((e.path() / "bin").string());
        std::sort(found.begin(), found.end(), [](const std::string& a, const std::string& b) {
            return a.size() != b.size() ? a.size() < b.size() : a < b; // 9.6 < 15
        });
        return found.empty() ? std::string() : found.back();
    }

    std::filesystem::path dir_;
    int port_ = 0;
    std::string stopCommand_, restartCommand_;
};

} // namespace cutcell::test
