#include "devices/record/user_directory.h"

#include <sodium.h>

#include <optional>

namespace cutcell {
namespace {

// 1-32 characters of letters, digits, '.', '_' and '-': a name that prints in any log line.
Outcome checkName(const std::string& name) {
    const bool valid =
        !name.empty() && name.size() <= 32 &&
        name.find_first_not_of("abcdefghijklmnopqrstuvwxyz"
                               "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789._-") == std::string::npos;
    if (valid) return Outcome::done();
    return Outcome::refuse("user name \"" + name.substr(0, 40) +
                               "\" is not valid: 1 to 32 letters, digits, '.', '_' or '-'",
                           "user");
}

Outcome checkPassword(const std::string& password) {
    const auto n = static_cast<int>(password.size());
    if (n < UserDirectory::kMinPasswordLength)
        return Outcome::refuse("the password has " + std::to_string(n) +
                                   " characters; it needs at least " +
                                   std::to_string(UserDirectory::kMinPasswordLength),
                               "password");
    if (n > UserDirectory::kMaxPasswordLength)
        return Outcome::refuse("the password has " + std::to_string(n) + " characters; at most " +
                                   std::to_string(UserDirectory::kMaxPasswordLength) + " are taken",
                               "password");
    return Outcome::done();
}

// Argon2id (libsodium's default for crypto_pwhash_str) at its interactive limits.
std::string hashPassword(const std::string& password) {
    char out[crypto_pwhash_STRBYTES];
    if (crypto_pwhash_str(out, password.data(), password.size(), crypto_pwhash_OPSLIMIT_INTERACTIVE,
                          crypto_pwhash_MEMLIMIT_INTERACTIVE) != 0)
        throw RecordError("users: no memory to hash a password (Argon2id needs 64 MiB)");
    return out;
}

// A name as the trail may print it: at most 40 bytes of printable ASCII, anything else as '?'
// (a byte cut out of a UTF-8 character would be refused by PostgreSQL's text).
std::string printable(const std::string& name) {
    std::string out = name.substr(0, 40);
    for (char& c : out)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
    return out;
}

// A hash of no one's password, checked for an unknown name (made once, at the first use).
const std::string& dummyHash() {
    static const std::string hash = [] {
        unsigned char random[16];
        randombytes_buf(random, sizeof random);
        return hashPassword(std::string(reinterpret_cast<const char*>(random), sizeof random));
    }();
    return hash;
}

struct Row {
    UserLevel level;
    std::string hash;
    int failed;
    std::int64_t lockedUntil;
};

std::optional<Row> findUser(RecordDb& db, const std::string& name) {
    const SqlRows r = db.query("SELECT level, pwhash, failed_logins, locked_until_ms FROM users "
                               "WHERE name = ?1",
                               {name});
    if (r.empty()) return std::nullopt;
    return Row{parseUserLevel(r[0].text(0)).value_or(UserLevel::Operator), r[0].text(1),
               static_cast<int>(r[0].integer(2)), r[0].integer(3)};
}

std::int64_t administrators(RecordDb& db) {
    const SqlRows r = db.query("SELECT count(*) FROM users WHERE level = 'administrator'");
    return r.empty() ? 0 : r[0].integer(0);
}

} // namespace

UserDirectory::UserDirectory(const std::string& where, AuditSink& audit, Clock clock)
    : audit_(audit), clock_(std::move(clock)), db_(openRecordDb(where)) {
    if (sodium_init() < 0) throw RecordError("users: libsodium cannot start");
}

UserDirectory::~UserDirectory() = default;

std::vector<UserAccount> UserDirectory::users() const {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<UserAccount> out;
    for (const SqlRow& r : db_->query("SELECT name, level, created_ms, failed_logins, "
                                      "locked_until_ms FROM users ORDER BY name"))
        out.push_back({r.text(0), parseUserLevel(r.text(1)).value_or(UserLevel::Operator),
                       r.integer(2), static_cast<int>(r.integer(3)), r.integer(4)});
    return out;
}

bool UserDirectory::hasAdministrator() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return administrators(*db_) > 0;
}

Outcome UserDirectory::addUser(const std::string& name, UserLevel level,
                               const std::string& password, const std::string& actor) {
    if (Outcome o = checkName(name); !o.ok()) return o;
    if (Outcome o = checkPassword(password); !o.ok()) return o;
    std::lock_guard<std::mutex> lock(mutex_);
    if (findUser(*db_, name)) return Outcome::refuse("user " + name + " exists already", "user");
    if (level != UserLevel::Administrator && administrators(*db_) == 0)
        return Outcome::refuse("the first user must be an administrator (level "
                               "\"administrator\"), not " +
                                   std::string(userLevelName(level)),
                               "level");
    db_->query("INSERT INTO users (name, level, pwhash, created_ms) VALUES (?1, ?2, ?3, ?4)",
               {name, std::string(userLevelName(level)), hashPassword(password), clock_()});
    audit_.append(
        {clock_(), actor, audit_event::kUserAdded, name, "", userLevelName(level), "", ""});
    return Outcome::done();
}

Outcome UserDirectory::removeUser(const std::string& name, const std::string& actor) {
    std::lock_guard<std::mutex> lock(mutex_);
    const std::optional<Row> row = findUser(*db_, name);
    if (!row) return Outcome::refuse("no user " + name.substr(0, 40), "user");
    if (row->level == UserLevel::Administrator && administrators(*db_) == 1)
        return Outcome::refuse("user " + name + " is the last administrator: add another one first",
                               "user");
    db_->query("DELETE FROM users WHERE name = ?1", {name});
    audit_.append(
        {clock_(), actor, audit_event::kUserRemoved, name, userLevelName(row->level), "", "", ""});
    return Outcome::done();
}

Outcome UserDirectory::setPassword(const std::string& name, const std::string& password,
                                   const std::string& actor) {
    if (Outcome o = checkPassword(password); !o.ok()) return o;
    std::lock_guard<std::mutex> lock(mutex_);
    if (!findUser(*db_, name)) return Outcome::refuse("no user " + name.substr(0, 40), "user");
    db_->query("UPDATE users SET pwhash = ?2, failed_logins = 0, locked_until_ms = 0 "
               "WHERE name = ?1",
               {name, hashPassword(password)});
    audit_.append({clock_(), actor, audit_event::kPasswordChanged, name, "", "", "", ""});
    return Outcome::done();
}

Outcome UserDirectory::setLevel(const std::string& name, UserLevel level,
                                const std::string& actor) {
    std::lock_guard<std::mutex> lock(mutex_);
    const std::optional<Row> row = findUser(*db_, name);
    if (!row) return Outcome::refuse("no user " + name.substr(0, 40), "user");
    if (row->level == UserLevel::Administrator && level != UserLevel::Administrator &&
        administrators(*db_) == 1)
        return Outcome::refuse("user " + name + " is the last administrator", "level");
    db_->query("UPDATE users SET level = ?2 WHERE name = ?1",
               {name, std::string(userLevelName(level))});
    audit_.append({clock_(), actor, audit_event::kLevelChanged, name, userLevelName(row->level),
                   userLevelName(level), "", ""});
    return Outcome::done();
}

LoginResult UserDirectory::login(const std::string& name, const std::string& password) {
    std::lock_guard<std::mutex> lock(mutex_);
    const std::int64_t now = clock_();
    // The operator is not told whether the name or the password was wrong; the trail is.
    const Outcome wrong = Outcome::refuse("user name or password wrong", "password");
    const std::optional<Row> row = checkName(name).ok() ? findUser(*db_, name) : std::nullopt;
    if (!row) {
        // The same work as for a user's password: the time taken does not tell names apart.
        const std::string& dummy = dummyHash();
        if (crypto_pwhash_str_verify(dummy.c_str(), password.data(), password.size()) == 0)
            return {wrong}; // no one's password: never a match, the time is what counts
        audit_.append({now, printable(name), audit_event::kLoginFailed, printable(name), "", "", "",
                       "no such user"});
        return {wrong};
    }
    const auto lockedOut = [&](std::int64_t until) {
        const std::int64_t left_s = (until - now + 999) / 1000;
        audit_.append({now, name, audit_event::kLoginFailed, name, "", "", "",
                       "locked out for " + std::to_string(left_s) + " s more"});
        return LoginResult{Outcome::refuse("user " + name + " is locked out for " +
                                               std::to_string(left_s) + " s more after " +
                                               std::to_string(kMaxFailedLogins) + " failed log-ins",
                                           "user")};
    };
    if (row->lockedUntil > now) return lockedOut(row->lockedUntil);
    // The attempt counts before the password is checked, in one statement: attempts of other
    // processes (a CLI beside the GUI) started at the same time each count too.
    int failed = 0;
    {
        const SqlRows count = db_->query("UPDATE users SET failed_logins = failed_logins + 1 "
                                         "WHERE name = ?1 RETURNING failed_logins, locked_until_ms",
                                         {name});
        if (count.empty()) return {wrong}; // removed meanwhile
        failed = static_cast<int>(count[0].integer(0));
        if (count[0].integer(1) > now) return lockedOut(count[0].integer(1));
    }
    const bool right =
        failed <= kMaxFailedLogins &&
        crypto_pwhash_str_verify(row->hash.c_str(), password.data(), password.size()) == 0;
    if (right) {
        db_->query("UPDATE users SET failed_logins = 0, locked_until_ms = 0 WHERE name = ?1",
                   {name});
        audit_.append(
            {now, name, audit_event::kLogin, name, "", userLevelName(row->level), "", ""});
        return {Outcome::done(), row->level};
    }
    if (failed >= kMaxFailedLogins) {
        db_->query("UPDATE users SET failed_logins = 0, locked_until_ms = ?2 WHERE name = ?1",
                   {name, now + kLockoutMs});
        audit_.append({now, name, audit_event::kLockedOut, name, "", "", "",
                       std::to_string(failed) + " failed log-ins: locked for " +
                           std::to_string(kLockoutMs / 1000) + " s"});
        return {Outcome::refuse("user name or password wrong; " + std::to_string(failed) +
                                    " failed log-ins: user " + name + " is locked out for " +
                                    std::to_string(kLockoutMs / 1000) + " s",
                                "password")};
    }
    audit_.append({now, name, audit_event::kLoginFailed, name, "", "", "",
                   "wrong password (" + std::to_string(failed) + " of " +
                       std::to_string(kMaxFailedLogins) + ")"});
    return {wrong};
}

void UserDirectory::logout(const std::string& name, const std::string& reason) {
    audit_.append({clock_(), name, audit_event::kLogout, name, "", "", "", reason});
}

std::optional<UserLevel> UserDirectory::levelOf(const std::string& name) const {
    std::lock_guard<std::mutex> lock(mutex_);
    const std::optional<Row> row = findUser(*db_, name);
    if (!row) return std::nullopt;
    return row->level;
}

bool UserDirectory::hasUsers() const {
    std::lock_guard<std::mutex> lock(mutex_);
    const SqlRows r = db_->query("SELECT count(*) FROM users");
    return !r.empty() && r[0].integer(0) > 0;
}

std::string UserDirectory::storedHash(const std::string& name) const {
    std::lock_guard<std::mutex> lock(mutex_);
    const std::optional<Row> row = findUser(*db_, name);
    return row ? row->hash : std::string();
}

} // namespace cutcell
