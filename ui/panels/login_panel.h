#pragma once
// The operator column's log-in (user levels): who is logged in and at which level, or a name
// and a password to log in with. Inline, never a dialog: a modal dialog would stand between the
// operator and the E-STOP. Hidden in single-user mode.
//
// Threading contract: GUI thread only.
#include <QWidget>

class QLabel;
class QLineEdit;
class QPushButton;

namespace CutCell::ui {

class AccessControl;

class LoginPanel : public QWidget {
    Q_OBJECT
  public:
    LoginPanel(AccessControl* access, QWidget* parent = nullptr);

    void refresh();

  private:
    void submit();

    AccessControl* access_;
    QLabel* who_;
    QLineEdit* name_;
    QLineEdit* password_;
    QPushButton* logIn_;
    QPushButton* logOut_;
    QLabel* message_;
};

} // namespace CutCell::ui
