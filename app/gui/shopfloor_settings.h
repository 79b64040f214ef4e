#pragma once
// The shop-floor link's settings at the station (issue 26): its configuration file
// (devices/shopfloor/shopfloor_config.h: a file of its own, not the job) edited by the engineer
// level where user levels exist. Every field of the file; Save checks with the reader's own
// checks (the first problem shown in the dialog - it names the key, the value, the unit and the
// limit - and nothing written), writes the file atomically, puts one audit event per changed
// key in the trail and restarts the link on the new file. The dialog stays open and shows the
// restarted link's line: a link that does not come up is corrected at once. A password never
// goes into the file, only the name of a file whose first line is the password.
//
// Threading contract: GUI thread only.
#include "devices/shopfloor/shopfloor_config.h"

#include <QDialog>
#include <QPointer>

#include <functional>
#include <string>
#include <utility>
#include <vector>

class QCheckBox;
class QLabel;
class QLineEdit;

namespace CutCell::ui {
class AccessControl;
class DecimalField;
class WholeNumberField;
} // namespace CutCell::ui

namespace cutcell::app {

// The trail's event for one changed key of the file: key, old value, new value, unit (numbers
// in C notation); the file in the detail.
inline constexpr const char* kShopfloorSettingChanged = "shopfloor setting changed";

// "" when the link's settings may be changed now, else why not. Without a user list (no access
// control, or single-user mode) anyone may; with users, the engineer level and above.
QString shopfloorSettingsLockReason(const CutCell::ui::AccessControl* access);

class ShopfloorSettingsDialog : public QDialog {
    Q_OBJECT
  public:
    // Closes the link and opens it on the saved file; returns the line for the operator.
    using Restart = std::function<std::string()>;
    // path: the file edited, read now (the defaults when it does not exist yet). access: null
    // without users (nothing audited); the dialog closes when its user may no longer edit.
    ShopfloorSettingsDialog(std::string path, CutCell::ui::AccessControl* access, Restart restart,
                            QWidget* parent = nullptr);
    ~ShopfloorSettingsDialog() override;

    const std::string& path() const { return path_; }
    // The fields as a configuration (not checked).
    shopfloor::ShopfloorConfig edited() const;
    // What Save does: true when the file was written and the link restarted; false with the
    // problem shown in the dialog (nothing written).
    bool save();

  signals:
    // After a save: the line the restarted link gave.
    void saved(const QString& line);

  private:
    void showConfig(const shopfloor::ShopfloorConfig& c);
    QWidget* fileRow(QLineEdit* field, const QString& title);
    void browse(QLineEdit* field, const QString& title);
    void showProblem(const QString& text);
    void auditChanges(const shopfloor::ShopfloorConfig& before,
                      const shopfloor::ShopfloorConfig& after);

    std::string path_;
    QPointer<CutCell::ui::AccessControl> access_;
    Restart restart_;
    shopfloor::ShopfloorConfig current_; // the file as last read or written
    QCheckBox* enabled_;
    QLineEdit* host_;
    CutCell::ui::WholeNumberField* port_;
    QLineEdit* groupId_;
    QLineEdit* edgeNodeId_;
    QLineEdit* username_;
    QLineEdit* passwordFile_;
    QLineEdit* caFile_;
    QLineEdit* certFile_;
    QLineEdit* keyFile_;
    CutCell::ui::DecimalField* axisRate_;
    CutCell::ui::WholeNumberField* capacity_;
    CutCell::ui::WholeNumberField* keepalive_;
    QLabel* problem_;
    QLabel* result_;
    std::vector<std::pair<std::string, QWidget*>> fieldOfKey_; // to mark the field a problem names
};

} // namespace cutcell::app
