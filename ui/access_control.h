#pragma once
// Who is at the operator station and what they may change (issue 25's user levels). With no
// users in the record the station runs in single-user mode: no log-in, every field editable,
// the desktop's user named in the trail. With users, nobody is logged in at the start: jobs can
// be viewed and E-STOP and feed hold work for everyone, but Start and every parameter need a
// log-in, and each field needs the level core gives its key (core/machine/parameter_level.h).
// An idle station logs its user out (10 minutes by default). Log-ins, log-outs and what the
// station does on a user's behalf go to the audit trail.
//
// Threading contract: GUI thread only.
#include "core/record/audit.h"

#include <QObject>
#include <QString>

#include <optional>
#include <string>

class QTimer;

namespace cutcell {
class MachineModule;
struct Job;
} // namespace cutcell

namespace CutCell::ui {

class AccessControl : public QObject {
    Q_OBJECT
  public:
    // users / audit: null for none (single-user mode, no trail). They outlive this object.
    AccessControl(cutcell::UserAuthenticator* users, cutcell::AuditSink* audit, QString desktopUser,
                  QObject* parent = nullptr);
    ~AccessControl() override;
    // The station's access control: the one made last and still alive (null when there is none:
    // no user levels, every edit allowed). For windows that are not given it (the cut-chart
    // editor opened from a form).
    static AccessControl* current();

    bool singleUser() const;
    bool loggedIn() const { return level_.has_value(); }
    // The logged-in user; in single-user mode the desktop's user; "" when logged out.
    QString user() const;
    std::optional<cutcell::UserLevel> level() const { return level_; }
    // "" when the key may be changed now, else why not (the level it needs).
    QString lockReason(const std::string& key, const cutcell::MachineModule* machine) const;
    // "" when a job file may replace the current job, else why not: a job for another machine
    // or one that changes a machine parameter needs the engineer level (the process
    // parameters are the job's own: any user may open them).
    QString openLockReason(const cutcell::Job& from, const cutcell::Job& to) const;
    // "" when a run may be started now, else why not.
    QString runLockReason() const;

    // Refused with the reason the operator may see (a wrong password, a lock-out). Waits for
    // the password's check (Argon2id, ~0.1 s): tests and tools; the panel uses logInLater.
    cutcell::Outcome logIn(const QString& name, const QString& password);
    // The same off the GUI thread (the E-STOP stays live meanwhile): loginFinished tells.
    void logInLater(const QString& name, const QString& password);
    bool loggingIn() const { return loggingIn_; }
    // The user list could not be opened (`why`): every field is locked, never opened.
    void setUnavailable(const QString& why);
    // Reads the user list again: users added or removed meanwhile (the CLI), the logged-in
    // user's level changed or the user removed. Every refreshMs (5 s) and at each log-in.
    void refreshUsers();
    void setRefreshMs(int ms);
    void logOut(const QString& reason = {});

    int idleTimeoutS() const { return idleTimeoutS_; }
    void setIdleTimeoutS(int seconds);

    // One event in the trail by the current user ("(not logged in)" when nobody is).
    void audit(const char* event, const QString& key = {}, const QString& oldValue = {},
               const QString& newValue = {}, const QString& unit = {}, const QString& detail = {});

  signals:
    void changed();
    void loginFinished(const cutcell::Outcome& outcome);
    // Before the user goes (what is pending in their name is written first).
    void aboutToLogOut();

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    cutcell::UserAuthenticator* users_;
    cutcell::AuditSink* audit_;
    QString desktopUser_;
    QString user_;
    std::optional<cutcell::UserLevel> level_;
    cutcell::Outcome apply(const QString& name, const cutcell::LoginAnswer& answer);

    QTimer* idle_;
    QTimer* refresh_;
    int idleTimeoutS_ = 600;
    bool hasUsers_ = false;
    bool loggingIn_ = false;
    QString unavailable_;
};

QString userLevelText(cutcell::UserLevel level); // in the GUI's language

} // namespace CutCell::ui
