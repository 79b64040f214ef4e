#include "shopfloor_settings.h"

#include "core/job/section_reader.h"
#include "core/record/audit.h"
#include "ui/access_control.h"
#include "ui/forms/number_fields.h"

#include <QCheckBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QStyle>
#include <QVBoxLayout>

#include <filesystem>
#include <system_error>

namespace cutcell::app {
namespace {

using shopfloor::ShopfloorConfig;

// One key of the file as the trail records it (numbers in C notation, as the file has them).
struct Setting {
    const char* key;
    const char* unit;
    std::string value;
};

std::vector<Setting> settingsOf(const ShopfloorConfig& c) {
    return {{"enabled", "", c.enabled ? "true" : "false"},
            {"host", "", c.host},
            {"port", "", std::to_string(c.port)},
            {"group_id", "", c.group_id},
            {"edge_node_id", "", c.edge_node_id},
            {"username", "", c.username},
            {"password_file", "", c.password_file},
            {"tls.ca_file", "", c.tls.ca_file},
            {"tls.cert_file", "", c.tls.cert_file},
            {"tls.key_file", "", c.tls.key_file},
            {"axis_rate_hz", "Hz", num(c.axis_rate_hz)},
            {"store_forward_capacity", "messages", std::to_string(c.store_forward_capacity)},
            {"keepalive_s", "s", std::to_string(c.keepalive_s)}};
}

QString fromStd(const std::string& s) {
    return QString::fromStdString(s);
}

void markInvalid(QWidget* w, bool invalid) {
    if (w->property("invalid").toBool() == invalid) return;
    w->setProperty("invalid", invalid);
    w->style()->unpolish(w);
    w->style()->polish(w);
}

} // namespace

QString shopfloorSettingsLockReason(const CutCell::ui::AccessControl* access) {
    using cutcell::UserLevel;
    if (!access || access->singleUser()) return {};
    const QString engineer = CutCell::ui::userLevelText(UserLevel::Engineer);
    if (!access->level())
        return ShopfloorSettingsDialog::tr("Log in to change the shop-floor link's settings "
                                           "(needs the %1 level)")
            .arg(engineer);
    if (*access->level() >= UserLevel::Engineer) return {};
    return ShopfloorSettingsDialog::tr(
               "The shop-floor link's settings need the %1 level (%2 is logged in as %3)")
        .arg(engineer, access->user(), CutCell::ui::userLevelText(*access->level()));
}

ShopfloorSettingsDialog::ShopfloorSettingsDialog(std::string path,
                                                 CutCell::ui::AccessControl* access,
                                                 Restart restart, QWidget* parent)
    : QDialog(parent), path_(std::move(path)), access_(access), restart_(std::move(restart)),
      enabled_(
          new QCheckBox(tr("Link on: publish the cell's state, take jobs from the network"), this)),
      host_(new QLineEdit(this)), port_(new CutCell::ui::WholeNumberField(this)),
      groupId_(new QLineEdit(this)), edgeNodeId_(new QLineEdit(this)),
      username_(new QLineEdit(this)), passwordFile_(new QLineEdit(this)),
      caFile_(new QLineEdit(this)), certFile_(new QLineEdit(this)), keyFile_(new QLineEdit(this)),
      axisRate_(new CutCell::ui::DecimalField(this)),
      capacity_(new CutCell::ui::WholeNumberField(this)),
      keepalive_(new CutCell::ui::WholeNumberField(this)), problem_(new QLabel(this)),
      result_(new QLabel(this)) {
    setObjectName("shopfloorSettings");
    setWindowTitle(tr("Shop-floor link"));
    fieldOfKey_ = {{"enabled", enabled_},
                   {"host", host_},
                   {"port", port_},
                   {"group_id", groupId_},
                   {"edge_node_id", edgeNodeId_},
                   {"username", username_},
                   {"password_file", passwordFile_},
                   {"tls.ca_file", caFile_},
                   {"tls.cert_file", certFile_},
                   {"tls.key_file", keyFile_},
                   {"axis_rate_hz", axisRate_},
                   {"store_forward_capacity", capacity_},
                   {"keepalive_s", keepalive_}};
    const char* names[] = {"shopfloorEnabled",      "shopfloorHost",       "shopfloorPort",
                           "shopfloorGroupId",      "shopfloorEdgeNodeId", "shopfloorUsername",
                           "shopfloorPasswordFile", "shopfloorCaFile",     "shopfloorCertFile",
                           "shopfloorKeyFile",      "shopfloorAxisRate",   "shopfloorCapacity",
                           "shopfloorKeepalive"};
    for (std::size_t i = 0; i < fieldOfKey_.size(); ++i) {
        fieldOfKey_[i].second->setObjectName(names[i]);
        fieldOfKey_[i].second->setToolTip(
            tr("Key in the file: %1").arg(fromStd(fieldOfKey_[i].first)));
    }
    // Wide ranges: the limits are the checker's (Save names them), not the fields' own.
    port_->setRange(0, 999999);
    axisRate_->setDecimals(3); // 0.125 Hz shown and saved as it is (2 decimals rounded it)
    axisRate_->setRange(0, 1000);
    axisRate_->setSuffix(" Hz");
    capacity_->setRange(0, 99999999);
    capacity_->setSuffix(" " + tr("messages"));
    keepalive_->setRange(0, 999999);
    keepalive_->setSuffix(" s");

    auto* form = new QFormLayout;
    // A number field's refusals name it by its label.
    const auto numberRow = [form](const QString& label, auto* field) {
        field->setFieldName(label);
        form->addRow(label, field);
    };
    form->addRow(enabled_);
    form->addRow(tr("Broker host"), host_);
    numberRow(tr("Broker port"), port_);
    form->addRow(tr("Sparkplug group id"), groupId_);
    form->addRow(tr("Edge node id (this cell)"), edgeNodeId_);
    form->addRow(tr("User name"), username_);
    form->addRow(tr("Password file"), fileRow(passwordFile_, tr("Password file")));
    form->addRow(tr("CA certificate file"), fileRow(caFile_, tr("CA certificate file")));
    form->addRow(tr("Client certificate file"), fileRow(certFile_, tr("Client certificate file")));
    form->addRow(tr("Client key file"), fileRow(keyFile_, tr("Client key file")));
    numberRow(tr("Axis positions rate"), axisRate_);
    numberRow(tr("Store-and-forward capacity"), capacity_);
    numberRow(tr("Keep-alive"), keepalive_);

    auto* hint = new QLabel(
        tr("The password itself is never stored here: the password file's first line is the "
           "password (readable by its owner only, chmod 600). Relative file names are read "
           "from the folder of %1.")
            .arg(fromStd(path_)),
        this);
    hint->setObjectName("hint");
    hint->setWordWrap(true);
    problem_->setObjectName("shopfloorSettingsProblem");
    problem_->setWordWrap(true);
    problem_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    problem_->setStyleSheet("color: #ffd0cc; background: #4a1c1c; border: 1px solid #ff4a3d; "
                            "border-radius: 3px; padding: 6px;");
    problem_->hide();
    result_->setObjectName("shopfloorSettingsResult");
    result_->setWordWrap(true);
    result_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* saveButton = new QPushButton(tr("Save"), this);
    saveButton->setObjectName("shopfloorSettingsSave");
    saveButton->setDefault(true);
    saveButton->setToolTip(tr("Check, write %1 and restart the link with it").arg(fromStd(path_)));
    auto* closeButton = new QPushButton(tr("Close"), this);
    closeButton->setObjectName("shopfloorSettingsClose");
    closeButton->setAutoDefault(false);
    auto* buttons = new QHBoxLayout;
    buttons->addStretch(1);
    buttons->addWidget(saveButton);
    buttons->addWidget(closeButton);
    auto* v = new QVBoxLayout(this);
    v->addLayout(form);
    v->addWidget(hint);
    v->addWidget(problem_);
    v->addWidget(result_);
    v->addLayout(buttons);
    connect(saveButton, &QPushButton::clicked, this, [this] { save(); });
    connect(closeButton, &QPushButton::clicked, this, &QDialog::reject);
    if (access_) {
        // A log-out (also the idle one) or a lower level closes the dialog, unsaved.
        connect(access_, &CutCell::ui::AccessControl::changed, this, [this] {
            if (!shopfloorSettingsLockReason(access_).isEmpty()) reject();
        });
        connect(access_, &QObject::destroyed, this, &QDialog::reject);
    }

    std::error_code ec;
    if (std::filesystem::exists(path_, ec)) try {
            current_ = shopfloor::loadShopfloorConfig(path_);
        } catch (const std::exception& e) {
            showProblem(tr("The file cannot be read (%1): the fields show the defaults; Save "
                           "replaces it.")
                            .arg(fromStd(e.what())));
        }
    showConfig(current_);
}

ShopfloorSettingsDialog::~ShopfloorSettingsDialog() = default;

QWidget* ShopfloorSettingsDialog::fileRow(QLineEdit* field, const QString& title) {
    auto* row = new QWidget(this);
    auto* h = new QHBoxLayout(row);
    h->setContentsMargins(0, 0, 0, 0);
    h->addWidget(field, 1);
    auto* browseButton = new QPushButton(tr("…"), row);
    browseButton->setObjectName(field->objectName() + "Browse");
    browseButton->setToolTip(tr("Choose the file"));
    browseButton->setAutoDefault(false);
    h->addWidget(browseButton);
    connect(browseButton, &QPushButton::clicked, this,
            [this, field, title] { browse(field, title); });
    return row;
}

void ShopfloorSettingsDialog::browse(QLineEdit* field, const QString& title) {
    const QString folder = QFileInfo(QString::fromStdString(path_)).absolutePath();
    const QString now = field->text();
    const QString start = now.isEmpty() ? folder : QFileInfo(QDir(folder), now).absoluteFilePath();
    const QString chosen = QFileDialog::getOpenFileName(this, title, start);
    if (chosen.isEmpty()) return;
    // A file beside the configuration keeps its bare name (the folder may move with it).
    const QFileInfo info(chosen);
    field->setText(info.absolutePath() == folder ? info.fileName() : info.absoluteFilePath());
}

void ShopfloorSettingsDialog::showConfig(const ShopfloorConfig& c) {
    enabled_->setChecked(c.enabled);
    host_->setText(fromStd(c.host));
    port_->setValue(c.port);
    groupId_->setText(fromStd(c.group_id));
    edgeNodeId_->setText(fromStd(c.edge_node_id));
    username_->setText(fromStd(c.username));
    passwordFile_->setText(fromStd(c.password_file));
    caFile_->setText(fromStd(c.tls.ca_file));
    certFile_->setText(fromStd(c.tls.cert_file));
    keyFile_->setText(fromStd(c.tls.key_file));
    axisRate_->setValue(c.axis_rate_hz);
    capacity_->setValue(c.store_forward_capacity);
    keepalive_->setValue(c.keepalive_s);
}

ShopfloorConfig ShopfloorSettingsDialog::edited() const {
    ShopfloorConfig c;
    c.enabled = enabled_->isChecked();
    c.host = host_->text().toStdString();
    c.port = port_->value();
    c.group_id = groupId_->text().toStdString();
    c.edge_node_id = edgeNodeId_->text().toStdString();
    c.username = username_->text().toStdString();
    c.password_file = passwordFile_->text().toStdString();
    c.tls.ca_file = caFile_->text().toStdString();
    c.tls.cert_file = certFile_->text().toStdString();
    c.tls.key_file = keyFile_->text().toStdString();
    c.axis_rate_hz = axisRate_->value();
    c.store_forward_capacity = capacity_->value();
    c.keepalive_s = keepalive_->value();
    return c;
}

void ShopfloorSettingsDialog::showProblem(const QString& text) {
    problem_->setText(text);
    problem_->setVisible(!text.isEmpty());
}

bool ShopfloorSettingsDialog::save() {
    for (const auto& [key, field] : fieldOfKey_)
        markInvalid(field, false);
    showProblem({});
    if (const QString why = shopfloorSettingsLockReason(access_); !why.isEmpty()) {
        showProblem(tr("Not saved: %1").arg(why));
        return false;
    }
    const ShopfloorConfig c = edited();
    try {
        shopfloor::checkShopfloorConfig(c); // the reader's checks, the ids' included
    } catch (const shopfloor::ShopfloorConfigError& e) {
        showProblem(tr("Not saved: %1").arg(fromStd(e.what())));
        // The field of the key the message names ("...: port = 70000 is outside ...").
        std::string what = e.what();
        if (const auto colon = what.find(": "); colon != std::string::npos)
            what = what.substr(colon + 2);
        for (const auto& [key, field] : fieldOfKey_)
            if (what.rfind(key, 0) == 0 && (what.size() == key.size() || what[key.size()] == ' ')) {
                markInvalid(field, true);
                field->setFocus();
                break;
            }
        return false;
    }
    try {
        const std::filesystem::path parentDir = std::filesystem::path(path_).parent_path();
        if (!parentDir.empty()) std::filesystem::create_directories(parentDir);
        shopfloor::saveShopfloorConfig(c, path_); // a temporary beside it, then a rename
    } catch (const std::exception& e) {
        showProblem(tr("Not saved: %1").arg(fromStd(e.what())));
        return false;
    }
    auditChanges(current_, c);
    current_ = c;
    const QString line = restart_ ? fromStd(restart_()) : QString();
    result_->setText(tr("Saved to %1. %2").arg(fromStd(path_), line));
    emit saved(line);
    return true;
}

void ShopfloorSettingsDialog::auditChanges(const ShopfloorConfig& before,
                                           const ShopfloorConfig& after) {
    if (!access_) return;
    const std::vector<Setting> was = settingsOf(before), now = settingsOf(after);
    for (std::size_t i = 0; i < now.size(); ++i)
        if (was[i].value != now[i].value)
            access_->audit(kShopfloorSettingChanged, now[i].key, fromStd(was[i].value),
                           fromStd(now[i].value), now[i].unit, fromStd(path_));
}

} // namespace cutcell::app
