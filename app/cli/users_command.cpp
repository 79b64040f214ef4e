// cutcell-cli users / audit: the station's users (user levels, Argon2id passwords) and the audit
// trail in the production record (devices/record/). The CLI is the engineer's tool: it edits job
// files without user levels; only the users themselves need an administrator's password once
// one exists (the first administrator is added by whoever sets the station up).
#include "cli_commands.h"
#include "record_text.h"

#include "core/json/json.h"
#include "devices/record/audit_trail.h"
#include "devices/record/run_record_store.h"
#include "devices/record/user_directory.h"

#include <cstdio>
#include <filesystem>
#include <string>

namespace cutcell::cli {
namespace {

std::string recordPath(const std::string& db) {
    return db.empty() ? defaultProductionDbPath() : db;
}

int refused(const char* action, const Outcome& o) {
    std::fprintf(stderr, "users %s: %s\n", action, o.message.c_str());
    return kFailure;
}

int listUsers(const UserDirectory& users, const std::string& path) {
    const auto all = users.users();
    if (all.empty()) {
        std::printf("no users in %s: the station runs in single-user mode (no log-in). "
                    "`cutcell-cli users add NAME --level administrator` adds the first.\n",
                    path.c_str());
        return kOk;
    }
    std::printf("%-32s %-13s %-20s %s\n", "user", "level", "created (UTC)", "locked until");
    for (const UserAccount& u : all)
        std::printf("%-32s %-13s %-20s %s\n", u.name.c_str(), userLevelName(u.level),
                    utcTime(u.created_ms).c_str(),
                    u.locked_until_ms > unixMsNow() ? utcTime(u.locked_until_ms).c_str() : "-");
    return kOk;
}

// Who authorises the change: an administrator by --admin and its password, or, before any
// administrator exists, the desktop user setting the station up. "" when refused (printed).
std::string authorise(UserDirectory& users, const UsersOptions& o) {
    if (!users.hasAdministrator()) return RunRecordStore::desktopUser();
    if (o.admin.empty()) {
        std::fprintf(stderr,
                     "users %s: changing users needs an administrator: --admin NAME (its "
                     "password on standard input)\n",
                     o.action.c_str());
        return {};
    }
    std::string password;
    if (!readSecret(("password of " + o.admin + ": ").c_str(), &password)) {
        std::fprintf(stderr, "users %s: no password for %s on standard input\n", o.action.c_str(),
                     o.admin.c_str());
        return {};
    }
    const LoginResult r = users.login(o.admin, password);
    if (!r.outcome.ok()) {
        std::fprintf(stderr, "users %s: %s\n", o.action.c_str(), r.outcome.message.c_str());
        return {};
    }
    if (r.level != UserLevel::Administrator) {
        std::fprintf(stderr, "users %s: %s is %s, not administrator\n", o.action.c_str(),
                     o.admin.c_str(), userLevelName(r.level));
        return {};
    }
    return o.admin;
}

bool newPassword(const UsersOptions& o, std::string* password) {
    if (readSecret(("new password of " + o.name + ": ").c_str(), password)) return true;
    std::fprintf(stderr, "users %s: no password for %s on standard input\n", o.action.c_str(),
                 o.name.c_str());
    return false;
}

bool levelOf(const UsersOptions& o, UserLevel* level) {
    if (const auto l = parseUserLevel(o.level)) {
        *level = *l;
        return true;
    }
    std::fprintf(stderr,
                 "users %s: --level \"%s\" is not a level: operator, setter, engineer or "
                 "administrator\n",
                 o.action.c_str(), o.level.c_str());
    return false;
}

} // namespace

int runUsers(const UsersOptions& o) {
    const std::string path = recordPath(o.db);
    try {
        AuditTrail trail(path);
        UserDirectory users(path, trail);
        if (o.action == "list") return listUsers(users, trail.where());
        if (o.name.empty()) {
            std::fprintf(stderr, "users %s: which user? (cutcell-cli users %s NAME)\n",
                         o.action.c_str(), o.action.c_str());
            return kUsage;
        }
        UserLevel level = UserLevel::Operator;
        if ((o.action == "add" || o.action == "level") && !levelOf(o, &level)) return kUsage;
        // A user changes its own password with the old one; anything else needs an
        // administrator.
        std::string actor;
        if (o.action == "passwd" && o.admin.empty() && users.hasAdministrator()) {
            std::string old;
            if (!readSecret(("password of " + o.name + ": ").c_str(), &old)) return kUsage;
            const LoginResult r = users.login(o.name, old);
            if (!r.outcome.ok()) return refused("passwd", r.outcome);
            actor = o.name;
        } else {
            actor = authorise(users, o);
            if (actor.empty()) return kFailure;
        }
        Outcome done;
        std::string password;
        if (o.action == "add") {
            if (!newPassword(o, &password)) return kUsage;
            done = users.addUser(o.name, level, password, actor);
        } else if (o.action == "passwd") {
            if (!newPassword(o, &password)) return kUsage;
            done = users.setPassword(o.name, password, actor);
        } else if (o.action == "remove") {
            done = users.removeUser(o.name, actor);
        } else {
            done = users.setLevel(o.name, level, actor);
        }
        if (!done.ok()) return refused(o.action.c_str(), done);
        std::printf("users %s: %s done in %s (by %s)\n", o.action.c_str(), o.name.c_str(),
                    trail.where().c_str(), actor.c_str());
        return kOk;
    } catch (const RecordError& e) {
        std::fprintf(stderr, "users: %s\n", e.what());
        return kFailure;
    }
}

int runAudit(const AuditOptions& o) {
    std::int64_t since = 0;
    if (!o.since.empty() && !parseDay(o.since, &since)) {
        std::fprintf(stderr, "audit: --since %s is not a day (YYYY-MM-DD)\n", o.since.c_str());
        return kUsage;
    }
    const std::string path = recordPath(o.db);
    if (!isPostgresConnection(path) && !std::filesystem::exists(path)) {
        std::fprintf(stderr, "audit: no production record at %s\n", path.c_str());
        return kFailure;
    }
    std::vector<RecordedAuditEvent> events;
    std::string where;
    try {
        const AuditTrail trail(path);
        events = trail.events(since);
        where = trail.where();
    } catch (const RecordError& e) {
        std::fprintf(stderr, "audit: %s\n", e.what());
        return kFailure;
    }
    if (o.json) {
        json::Array out;
        for (const RecordedAuditEvent& r : events) {
            json::Value v = AuditTrail::toJson(r);
            v.asObject().insert(v.asObject().begin() + 1, {"time", utcTime(r.event.unix_ms)});
            out.push_back(std::move(v));
        }
        std::printf("%s", json::write(json::Value(std::move(out))).c_str());
        return kOk;
    }
    if (o.csv) {
        std::printf("id,time,actor,event,key,old,new,unit,detail\n");
        for (const auto& [id, e] : events)
            std::printf("%lld,%s,%s,%s,%s,%s,%s,%s,%s\n", static_cast<long long>(id),
                        utcTime(e.unix_ms).c_str(), csvField(e.actor).c_str(),
                        csvField(e.event).c_str(), csvField(e.key).c_str(),
                        csvField(e.old_value).c_str(), csvField(e.new_value).c_str(),
                        csvField(e.unit).c_str(), csvField(e.detail).c_str());
        return kOk;
    }
    for (const auto& [id, e] : events) {
        std::string change;
        if (!e.old_value.empty() || !e.new_value.empty())
            change =
                " " + e.old_value + " -> " + e.new_value + (e.unit.empty() ? "" : " " + e.unit);
        std::printf("%-6lld %-20s %-16s %-18s %s%s%s%s\n", static_cast<long long>(id),
                    utcTime(e.unix_ms).c_str(), e.actor.c_str(), e.event.c_str(), e.key.c_str(),
                    change.c_str(), e.detail.empty() ? "" : "  ", e.detail.c_str());
    }
    std::printf("%zu event(s) in %s\n", events.size(), where.c_str());
    return kOk;
}

} // namespace cutcell::cli
