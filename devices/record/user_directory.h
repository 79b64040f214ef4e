#pragma once
// The station's users in the production record (a SQLite file or a PostgreSQL database) (IEC
// 62443-4-2 CR 1.1 identification and authentication, CR 1.7 strength of password-based
// authentication, CR 1.11 unsuccessful login attempts). Passwords are stored only as Argon2id
// hashes (libsodium crypto_pwhash_str, its interactive limits: 2 passes over 64 MiB); at least 8
// characters; five failed log-ins lock the user out for a minute. The first user must be an
// administrator and the last administrator cannot be removed. Every change and every log-in, failed
// or not, goes to the audit trail.
#include "core/common/outcome.h"
#include "core/record/audit.h"
#include "devices/record/record_db.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace cutcell {

struct UserAccount {
    std::string name;
    UserLevel level = UserLevel::Operator;
    std::int64_t created_ms = 0;
    int failed_logins = 0;            // since the last success or lock-out
    std::int64_t locked_until_ms = 0; // 0: not locked
};

using LoginResult = LoginAnswer;

class UserDirectory final : public UserAuthenticator {
  public:
    static constexpr int kMinPasswordLength = 8;
    static constexpr int kMaxPasswordLength = 128;
    static constexpr int kMaxFailedLogins = 5;
    static constexpr std::int64_t kLockoutMs = 60'000;
    using Clock = std::function<std::int64_t()>; // ms since the epoch

    // Opens (creates, migrates) the record `where` (record_db.h); throws RecordError. `audit`
    // outlives this.
    UserDirectory(const std::string& where, AuditSink& audit, Clock clock = unixMsNow);
    ~UserDirectory() override;
    UserDirectory(const UserDirectory&) = delete;
    UserDirectory& operator=(const UserDirectory&) = delete;

    std::vector<UserAccount> users() const; // by name
    bool hasAdministrator() const;

    // `actor`: who does it (an administrator's name, or the desktop user for the first one).
    Outcome addUser(const std::string& name, UserLevel level, const std::string& password,
                    const std::string& actor);
    Outcome removeUser(const std::string& name, const std::string& actor);
    Outcome setPassword(const std::string& name, const std::string& password,
                        const std::string& actor);
    Outcome setLevel(const std::string& name, UserLevel level, const std::string& actor);

    bool hasUsers() const override;
    std::optional<UserLevel> levelOf(const std::string& name) const override;
    LoginResult login(const std::string& name, const std::string& password) override;
    void logout(const std::string& name, const std::string& reason = {}) override;

    // The stored hash (tests check it is Argon2id with crypto_pwhash_str_verify); "" if none.
    std::string storedHash(const std::string& name) const;

  private:
    AuditSink& audit_;
    Clock clock_;
    std::unique_ptr<RecordDb> db_; // [mutex_]
    mutable std::mutex mutex_;
};

} // namespace cutcell
