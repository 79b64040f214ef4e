#pragma once
// The station's user levels and its audit trail as core sees them (IEC 62443-4-2 CR 2.1
// authorisation, CR 2.8 auditable events). Who may change what is a level; what was done is an
// AuditEvent handed to an AuditSink. devices/record/ keeps users and the trail in the
// production record's SQLite file; the app wires it in.
#include "core/common/outcome.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace cutcell {

// Each level may do what the ones below it may.
enum class UserLevel : std::uint8_t {
    Operator,      // open jobs from the library, run, stop, recover, acknowledge
    Setter,        // + process parameters: speeds, bevel, cut chart, recovery
    Engineer,      // + machine parameters: DH, links, gains, limits, devices, E-STOP category
    Administrator, // + users
};

inline constexpr const char* userLevelName(UserLevel l) {
    switch (l) {
    case UserLevel::Operator:
        return "operator";
    case UserLevel::Setter:
        return "setter";
    case UserLevel::Engineer:
        return "engineer";
    case UserLevel::Administrator:
        return "administrator";
    }
    return "operator";
}

inline std::optional<UserLevel> parseUserLevel(std::string_view name) {
    for (UserLevel l :
         {UserLevel::Operator, UserLevel::Setter, UserLevel::Engineer, UserLevel::Administrator})
        if (name == userLevelName(l)) return l;
    return std::nullopt;
}

// What the trail records. The names are the trail's "event" column.
namespace audit_event {
inline constexpr const char* kLogin = "login";
inline constexpr const char* kLoginFailed = "login failed";
inline constexpr const char* kLockedOut = "locked out";
inline constexpr const char* kLogout = "logout";
inline constexpr const char* kUserAdded = "user added";
inline constexpr const char* kUserRemoved = "user removed";
inline constexpr const char* kPasswordChanged = "password changed";
inline constexpr const char* kLevelChanged = "level changed";
inline constexpr const char* kParameterChanged = "parameter changed";
inline constexpr const char* kEmergencyStop = "emergency stop";
inline constexpr const char* kReset = "reset";
inline constexpr const char* kOverrideChanged = "override changed";
inline constexpr const char* kRecovery = "recovery";
inline constexpr const char* kArchived = "archived";
} // namespace audit_event

struct AuditEvent {
    std::int64_t unix_ms = 0; // 0: the sink stamps it
    std::string actor;        // the user, or the desktop user for the CLI
    std::string event;        // one of audit_event
    std::string key;          // the job key or the user concerned ("" for none)
    std::string old_value, new_value, unit;
    std::string detail; // anything else worth a line (the job file, the reason)
};

struct LoginAnswer {
    Outcome outcome; // Refused with the reason an operator may see
    UserLevel level = UserLevel::Operator;
};

// Who may log in at the station (devices/record/: UserDirectory). With no users the
// station runs in single-user mode: no log-in, every field editable.
class UserAuthenticator {
  public:
    virtual ~UserAuthenticator() = default;
    virtual bool hasUsers() const = 0;
    // The user's level now (an administrator may have changed it since the log-in); none when
    // the user is gone.
    virtual std::optional<UserLevel> levelOf(const std::string& name) const = 0;
    virtual LoginAnswer login(const std::string& name, const std::string& password) = 0;
    // `reason`: "" when the user logged out, else why ("idle for 600 s").
    virtual void logout(const std::string& name, const std::string& reason) = 0;
};

class AuditSink {
  public:
    virtual ~AuditSink() = default;
    // Appends one event; never blocks the engine's cycle (called from the GUI or logger thread).
    virtual void append(const AuditEvent& event) = 0;
};

} // namespace cutcell
