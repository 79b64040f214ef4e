#include "ui/panels/login_panel.h"

#include "ui/access_control.h"

#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>

namespace CutCell::ui {

LoginPanel::LoginPanel(AccessControl* access, QWidget* parent)
    : QWidget(parent), access_(access), who_(new QLabel(this)), name_(new QLineEdit(this)),
      password_(new QLineEdit(this)), logIn_(new QPushButton(tr("Log in"), this)),
      logOut_(new QPushButton(tr("Log out"), this)), message_(new QLabel(this)) {
    setObjectName("loginPanel");
    who_->setObjectName("loginUser");
    name_->setObjectName("loginName");
    password_->setObjectName("loginPassword");
    logIn_->setObjectName("loginButton");
    logOut_->setObjectName("logoutButton");
    message_->setObjectName("loginMessage");
    name_->setPlaceholderText(tr("User"));
    password_->setPlaceholderText(tr("Password"));
    password_->setEchoMode(QLineEdit::Password);
    // Named for assistive technology and the real-input walkthrough (AT-SPI).
    name_->setAccessibleName(name_->placeholderText());
    password_->setAccessibleName(password_->placeholderText());
    message_->setWordWrap(true);
    who_->setWordWrap(true);
    // Two fields side by side at most: the operator column is 320 px wide.
    name_->setMinimumWidth(60);
    password_->setMinimumWidth(60);
    auto* g = new QGridLayout(this);
    g->setContentsMargins(6, 4, 6, 4);
    g->addWidget(who_, 0, 0, 1, 2);
    g->addWidget(name_, 1, 0);
    g->addWidget(password_, 1, 1);
    g->addWidget(logIn_, 2, 0, 1, 2);
    g->addWidget(logOut_, 2, 0, 1, 2);
    g->addWidget(message_, 3, 0, 1, 2);
    connect(logIn_, &QPushButton::clicked, this, &LoginPanel::submit);
    connect(password_, &QLineEdit::returnPressed, this, &LoginPanel::submit);
    connect(logOut_, &QPushButton::clicked, this, [this] { access_->logOut(); });
    connect(access_, &AccessControl::changed, this, &LoginPanel::refresh);
    connect(access_, &AccessControl::loginFinished, this, [this](const cutcell::Outcome& o) {
        message_->setText(o.ok() ? QString() : QString::fromStdString(o.message));
        refresh();
    });
    refresh();
}

void LoginPanel::refresh() {
    setVisible(!access_->singleUser());
    const bool in = access_->loggedIn();
    who_->setText(in ? tr("%1 (%2)").arg(access_->user(), userLevelText(*access_->level()))
                     : tr("Not logged in: E-STOP and feed hold work for everyone"));
    logOut_->setVisible(in);
    name_->setVisible(!in);
    password_->setVisible(!in);
    logIn_->setVisible(!in);
    logIn_->setEnabled(!access_->loggingIn());
    if (in) message_->clear();
    message_->setVisible(!message_->text().isEmpty());
}

void LoginPanel::submit() {
    // Checked off the GUI thread (Argon2id takes ~0.1 s): the E-STOP stays live meanwhile.
    access_->logInLater(name_->text(), password_->text());
    password_->clear(); // never kept, right or wrong
}

} // namespace CutCell::ui
