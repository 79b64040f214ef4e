#include "ui/access_control.h"

#include "core/job/job_diff.h"
#include "core/machine/machine_registry.h"
#include "core/machine/parameter_level.h"

#include <QCoreApplication>
#include <QEvent>
#include <QFutureWatcher>
#include <QTimer>
#include <QtConcurrent/QtConcurrentRun>

#include <exception>

namespace CutCell::ui {

QString userLevelText(cutcell::UserLevel level) {
    switch (level) {
    case cutcell::UserLevel::Operator:
        return AccessControl::tr("operator");
    case cutcell::UserLevel::Setter:
        return AccessControl::tr("setter");
    case cutcell::UserLevel::Engineer:
        return AccessControl::tr("engineer");
    case cutcell::UserLevel::Administrator:
        return AccessControl::tr("administrator");
    }
    return {};
}

namespace {
AccessControl* g_current = nullptr;
} // namespace

AccessControl* AccessControl::current() {
    return g_current;
}

AccessControl::AccessControl(cutcell::UserAuthenticator* users, cutcell::AuditSink* audit,
                             QString desktopUser, QObject* parent)
    : QObject(parent), users_(users), audit_(audit), desktopUser_(std::move(desktopUser)),
      idle_(new QTimer(this)), refresh_(new QTimer(this)) {
    idle_->setSingleShot(true);
    connect(refresh_, &QTimer::timeout, this, &AccessControl::refreshUsers);
    refresh_->start(5000);
    connect(idle_, &QTimer::timeout, this,
            [this] { logOut(QStringLiteral("idle for %1 s").arg(idleTimeoutS_)); });
    if (QCoreApplication::instance()) QCoreApplication::instance()->installEventFilter(this);
    refreshUsers();
    g_current = this;
}

AccessControl::~AccessControl() {
    if (g_current == this) g_current = nullptr;
    if (QCoreApplication::instance()) QCoreApplication::instance()->removeEventFilter(this);
}

bool AccessControl::singleUser() const {
    return unavailable_.isEmpty() && !hasUsers_;
}

void AccessControl::setUnavailable(const QString& why) {
    unavailable_ = why;
    emit changed();
}

void AccessControl::setRefreshMs(int ms) {
    refresh_->start(ms > 0 ? ms : 5000);
}

void AccessControl::refreshUsers() {
    if (!users_) return;
    bool changedNow = false;
    try {
        const bool has = users_->hasUsers();
        changedNow = has != hasUsers_;
        hasUsers_ = has;
        if (level_) {
            const std::optional<cutcell::UserLevel> now = users_->levelOf(user_.toStdString());
            if (!now) {
                logOut(QStringLiteral("the user was removed"));
                return;
            }
            if (*now != *level_) {
                audit(cutcell::audit_event::kLevelChanged, user_, userLevelName(*level_),
                      userLevelName(*now), {}, QStringLiteral("taken at the station"));
                level_ = now;
                changedNow = true;
            }
        }
    } catch (const std::exception& e) {
        // A list that cannot be read any more locks the fields; it never opens them.
        changedNow = unavailable_.isEmpty();
        unavailable_ = QString::fromUtf8(e.what());
    }
    if (changedNow) emit changed();
}

QString AccessControl::user() const {
    if (loggedIn()) return user_;
    return singleUser() ? desktopUser_ : QString();
}

QString AccessControl::lockReason(const std::string& key,
                                  const cutcell::MachineModule* machine) const {
    if (!unavailable_.isEmpty())
        return tr("The user list cannot be read (%1): the fields stay locked").arg(unavailable_);
    if (singleUser()) return {};
    const cutcell::UserLevel needed = cutcell::levelToChange(key, machine);
    if (!level_) return tr("Log in to change this (needs the %1 level)").arg(userLevelText(needed));
    if (*level_ >= needed) return {};
    return tr("Needs the %1 level (%2 is logged in as %3)")
        .arg(userLevelText(needed), user_, userLevelText(*level_));
}

QString AccessControl::openLockReason(const cutcell::Job& from, const cutcell::Job& to) const {
    if (singleUser() || (level_ && *level_ >= cutcell::UserLevel::Engineer)) return {};
    const QString who = level_ ? tr("%1 is logged in as %2").arg(user_, userLevelText(*level_))
                               : tr("nobody is logged in");
    if (from.machine != to.machine)
        return tr("it is a job for another machine (%1): opening it needs the %2 level (%3)")
            .arg(QString::fromStdString(to.machine), userLevelText(cutcell::UserLevel::Engineer),
                 who);
    const cutcell::MachineModule* machine = cutcell::findMachine(to.machine);
    for (const cutcell::ChangedKey& k : cutcell::changedKeys(from, to))
        if (cutcell::levelToChange(k.key, machine) == cutcell::UserLevel::Engineer)
            return tr("it changes %1 from %2 to %3: opening it needs the %4 level (%5)")
                .arg(QString::fromStdString(k.key), QString::fromStdString(k.from),
                     QString::fromStdString(k.to), userLevelText(cutcell::UserLevel::Engineer),
                     who);
    return {};
}

QString AccessControl::runLockReason() const {
    if (!unavailable_.isEmpty())
        return tr("the user list cannot be read (%1): repair it, or start with --record off to "
                  "run without users")
            .arg(unavailable_);
    if (singleUser() || loggedIn()) return {};
    return tr("log in to run (E-STOP and feed hold work without log-in)");
}

cutcell::Outcome AccessControl::logIn(const QString& name, const QString& password) {
    if (!users_) return cutcell::Outcome::refuse(tr("no user list here").toStdString());
    cutcell::LoginAnswer answer;
    try {
        answer = users_->login(name.trimmed().toStdString(), password.toStdString());
    } catch (const std::exception& e) {
        answer.outcome = cutcell::Outcome::refuse(e.what());
    }
    return apply(name.trimmed(), answer);
}

void AccessControl::logInLater(const QString& name, const QString& password) {
    if (!users_) {
        emit loginFinished(cutcell::Outcome::refuse(tr("no user list here").toStdString()));
        return;
    }
    if (loggingIn_) return;
    loggingIn_ = true;
    emit changed();
    auto* watcher = new QFutureWatcher<cutcell::LoginAnswer>(this);
    const QString who = name.trimmed();
    connect(watcher, &QFutureWatcher<cutcell::LoginAnswer>::finished, this, [this, watcher, who] {
        watcher->deleteLater();
        loggingIn_ = false;
        const cutcell::Outcome o = apply(who, watcher->result());
        emit changed();
        emit loginFinished(o);
    });
    cutcell::UserAuthenticator* users = users_;
    watcher->setFuture(QtConcurrent::run([users, who, password]() -> cutcell::LoginAnswer {
        try {
            return users->login(who.toStdString(), password.toStdString());
        } catch (const std::exception& e) {
            return {cutcell::Outcome::refuse(e.what()), cutcell::UserLevel::Operator};
        }
    }));
}

cutcell::Outcome AccessControl::apply(const QString& name, const cutcell::LoginAnswer& answer) {
    if (!answer.outcome.ok()) return answer.outcome;
    if (loggedIn() && user_ != name) logOut(QStringLiteral("%1 logged in").arg(name));
    user_ = name;
    level_ = answer.level;
    hasUsers_ = true;
    idle_->start(idleTimeoutS_ * 1000);
    emit changed();
    return cutcell::Outcome::done();
}

void AccessControl::logOut(const QString& reason) {
    if (!loggedIn()) return;
    emit aboutToLogOut();
    try {
        if (users_) users_->logout(user_.toStdString(), reason.toStdString());
    } catch (const std::exception&) {
        // The trail could not be written: the log-out itself still happens.
    }
    user_.clear();
    level_.reset();
    idle_->stop();
    emit changed();
}

void AccessControl::setIdleTimeoutS(int seconds) {
    idleTimeoutS_ = seconds > 0 ? seconds : 600;
    if (loggedIn()) idle_->start(idleTimeoutS_ * 1000);
}

void AccessControl::audit(const char* event, const QString& key, const QString& oldValue,
                          const QString& newValue, const QString& unit, const QString& detail) {
    if (!audit_) return;
    const QString who = user().isEmpty() ? QStringLiteral("(not logged in)") : user();
    try {
        audit_->append({0, who.toStdString(), event, key.toStdString(), oldValue.toStdString(),
                        newValue.toStdString(), unit.toStdString(), detail.toStdString()});
    } catch (const std::exception&) {
        // Never in the way of the machine: a trail that cannot be written is reported where it
        // is opened (app/gui/station_access.cpp), not at each command.
    }
}

bool AccessControl::eventFilter(QObject* watched, QEvent* event) {
    if (loggedIn()) switch (event->type()) {
        case QEvent::KeyPress:
        case QEvent::MouseButtonPress:
        case QEvent::Wheel:
        case QEvent::TouchBegin:
            idle_->start(idleTimeoutS_ * 1000);
            break;
        default:
            break;
        }
    return QObject::eventFilter(watched, event);
}

} // namespace CutCell::ui
