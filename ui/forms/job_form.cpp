#include "ui/forms/job_form.h"

#include "ui/forms/issue_text.h"

#include "ui/forms/number_fields.h"
#include "ui/shown_number.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStyle>
#include <QTableWidget>
#include <QTimer>
#include <QToolTip>
#include <QVBoxLayout>

#include <cmath>

namespace CutCell::ui {
namespace {

// The field's tooltip: its issues, then why it is read-only (user levels) if it is.
void showTip(QWidget* w, const QString& issues) {
    const QString locked = w->property("lockReason").toString();
    w->setToolTip(locked.isEmpty() ? issues : issues.isEmpty() ? locked : issues + "\n" + locked);
}

void setInvalid(QWidget* w, bool invalid, const QString& tip) {
    if (w->property("invalid").toBool() != invalid) {
        w->setProperty("invalid", invalid);
        w->style()->unpolish(w);
        w->style()->polish(w);
    }
    w->setProperty("issueTip", tip);
    showTip(w, tip);
}

// Read-only with the reason (user levels) or editable again. Text fields keep their text
// selectable; check boxes, choices and tables ignore input (their enabled state belongs to
// the machine's pages, ParameterTabs::applyMachine).
void setLocked(QWidget* w, const QString& reason) {
    const bool locked = !reason.isEmpty();
    if (auto* spin = qobject_cast<QAbstractSpinBox*>(w))
        spin->setReadOnly(locked);
    else if (auto* line = qobject_cast<QLineEdit*>(w))
        line->setReadOnly(locked);
    else if (auto* text = qobject_cast<QPlainTextEdit*>(w))
        text->setReadOnly(locked);
    else {
        w->setAttribute(Qt::WA_TransparentForMouseEvents, locked);
        w->setFocusPolicy(locked ? Qt::NoFocus : Qt::StrongFocus);
        // A group or a table marked with one key (the saw's queue): its own fields too.
        for (auto* field : w->findChildren<QAbstractSpinBox*>())
            field->setReadOnly(locked);
        for (auto* edit : w->findChildren<QLineEdit*>())
            edit->setReadOnly(locked);
    }
    if (w->property("locked").toBool() != locked) {
        w->setProperty("locked", locked);
        w->style()->unpolish(w);
        w->style()->polish(w);
    }
    w->setProperty("lockReason", reason);
    showTip(w, w->property("issueTip").toString());
}

} // namespace

JobForm::JobForm(JobEditor* editor, QWidget* parent)
    : QWidget(parent), editor_(editor), layout_(new QVBoxLayout(this)),
      issuesLabel_(new QLabel(this)) {
    issuesLabel_->setObjectName("formIssues");
    issuesLabel_->setWordWrap(true);
    issuesLabel_->setTextFormat(Qt::PlainText);
    issuesLabel_->hide();
    layout_->addWidget(issuesLabel_);
    connect(editor_, &JobEditor::jobReset, this, &JobForm::reload);
    connect(editor_, &JobEditor::issuesChanged, this, &JobForm::markIssues);
}

QWidget* JobForm::fieldFor(const std::string& key) const {
    auto it = fields_.find(key);
    if (it != fields_.end()) return it->second;
    for (const JobForm* sub : subForms_)
        if (QWidget* w = sub->fieldFor(key)) return w;
    return nullptr;
}

std::vector<std::string> JobForm::keys() const {
    std::vector<std::string> out;
    for (const auto& [k, w] : fields_)
        if (out.empty() || out.back() != k) out.push_back(k);
    for (const JobForm* sub : subForms_)
        for (const std::string& k : sub->keys())
            out.push_back(k);
    return out;
}

int JobForm::markedCount() const {
    int n = marked_;
    for (const JobForm* sub : subForms_)
        n += sub->markedCount();
    return n;
}

void JobForm::addSubForm(JobForm* form, int index) {
    subForms_.push_back(form);
    layout_->insertWidget(index, form);
}

void JobForm::registerField(const std::string& key, QWidget* w) {
    fields_.emplace(key, w);
    w->setProperty("jobKey", QString::fromStdString(key));
    w->setObjectName(QString::fromStdString(key));
}

void JobForm::alsoMark(const std::string& key, QWidget* w) {
    fields_.emplace(key, w);
}

QDoubleSpinBox* JobForm::bindDouble(const std::string& key, int decimals, DoubleRef ref) {
    auto* w = new DecimalField(this);
    w->setFieldName(QString::fromStdString(key));
    w->setDecimals(decimals);
    w->setRange(-1e9, 1e9);
    w->setKeyboardTracking(true);
    w->setAccelerated(true);
    w->setButtonSymbols(QAbstractSpinBox::NoButtons);
    w->setAlignment(Qt::AlignRight);
    // The wide range would make the box ~140 px wide at least: let the layout narrow it.
    w->setMinimumWidth(70);
    registerField(key, w);
    bindings_.push_back({w, [w, ref](const cutcell::Job& job) {
                             auto copy = job;
                             w->setValue(ref(copy));
                         }});
    connect(w, &QDoubleSpinBox::valueChanged, this, [this, key, ref](double v) {
        if (loading_) return;
        auto job = editor_->job();
        commit(key, QString::number(ref(job), 'g', 12), QString::number(v, 'g', 12),
               [&](cutcell::Job& j) { ref(j) = v; });
    });
    return w;
}

QSpinBox* JobForm::bindInt(const std::string& key, IntRef ref) {
    auto* w = new WholeNumberField(this);
    w->setFieldName(QString::fromStdString(key));
    w->setRange(-1000000000, 1000000000);
    w->setButtonSymbols(QAbstractSpinBox::NoButtons);
    w->setAlignment(Qt::AlignRight);
    w->setMinimumWidth(60);
    registerField(key, w);
    bindings_.push_back({w, [w, ref](const cutcell::Job& job) {
                             auto copy = job;
                             w->setValue(ref(copy));
                         }});
    connect(w, &QSpinBox::valueChanged, this, [this, key, ref](int v) {
        if (loading_) return;
        auto job = editor_->job();
        commit(key, QString::number(ref(job)), QString::number(v),
               [&](cutcell::Job& j) { ref(j) = v; });
    });
    return w;
}

QCheckBox* JobForm::bindBool(const std::string& key, const QString& text, BoolRef ref) {
    auto* w = new QCheckBox(text, this);
    registerField(key, w);
    bindings_.push_back({w, [w, ref](const cutcell::Job& job) {
                             auto copy = job;
                             w->setChecked(ref(copy));
                         }});
    connect(w, &QCheckBox::toggled, this, [this, key, ref](bool v) {
        if (loading_) return;
        commit(key, v ? "false" : "true", v ? "true" : "false",
               [&](cutcell::Job& j) { ref(j) = v; });
    });
    return w;
}

QLineEdit* JobForm::bindString(const std::string& key, StringRef ref) {
    auto* w = new QLineEdit(this);
    registerField(key, w);
    bindings_.push_back({w, [w, ref](const cutcell::Job& job) {
                             auto copy = job;
                             w->setText(QString::fromStdString(ref(copy)));
                             w->setCursorPosition(0); // show the start of long names
                         }});
    connect(w, &QLineEdit::textEdited, this, [this, key, ref](const QString& v) {
        if (loading_) return;
        auto job = editor_->job();
        commit(key, QString::fromStdString(ref(job)), v,
               [&](cutcell::Job& j) { ref(j) = v.toStdString(); });
    });
    return w;
}

QPlainTextEdit* JobForm::bindText(const std::string& key, StringRef ref) {
    auto* w = new QPlainTextEdit(this);
    w->setTabChangesFocus(true);
    registerField(key, w);
    bindings_.push_back({w, [w, ref](const cutcell::Job& job) {
                             auto copy = job;
                             w->setPlainText(QString::fromStdString(ref(copy)));
                         }});
    connect(w, &QPlainTextEdit::textChanged, this, [this, key, w, ref] {
        if (loading_) return;
        const auto text = w->toPlainText().toStdString();
        auto current = editor_->job();
        if (ref(current) == text) return;
        commit(key, QString::fromStdString(ref(current)), QString::fromStdString(text),
               [&](cutcell::Job& j) { ref(j) = text; });
    });
    return w;
}

QComboBox* JobForm::bindChoice(const std::string& key, const QStringList& items,
                               std::function<int(const cutcell::Job&)> get,
                               std::function<void(cutcell::Job&, int)> set) {
    auto* w = new QComboBox(this);
    w->addItems(items);
    registerField(key, w);
    bindings_.push_back({w, [w, get](const cutcell::Job& job) { w->setCurrentIndex(get(job)); }});
    connect(w, &QComboBox::currentIndexChanged, this, [this, key, items, get, set](int i) {
        if (loading_ || i < 0) return;
        const int old = get(editor_->job());
        commit(key, items.value(old), items.value(i), [&](cutcell::Job& j) { set(j, i); });
    });
    return w;
}

QString JobForm::fieldLabel(const char* label) {
    return QCoreApplication::translate("SectionField", label);
}

QString JobForm::displayUnit(const char* unit) {
    // A unit that is a word ("strokes") in the GUI's language (tools/core_labels.py).
    QString u = QCoreApplication::translate("SectionUnit", unit);
    if (u == QLatin1String("1")) return QStringLiteral(" "); // a ratio: the row keeps its column
    u.replace(QLatin1String("^2"), QStringLiteral("²"));
    u.replace(QLatin1String("^3"), QStringLiteral("³"));
    return u;
}

void JobForm::setColumnCount(QTableWidget* table, int n) {
    table->setColumnCount(n);
}

int JobForm::rowCount(const QTableWidget* table) {
    return table->rowCount();
}

void JobForm::setColumnHeader(QTableWidget* table, int column, const char* label, const char* unit,
                              double lo, double hi, bool checked) {
    const QString u = displayUnit(unit);
    // A ratio (no unit) keeps the header's second line, without an empty "[]".
    auto* item = new QTableWidgetItem(fieldLabel(label) +
                                      (u.trimmed().isEmpty()
                                           ? QStringLiteral("\n")
                                           : QStringLiteral("\n[") + u + QStringLiteral("]")));
    if (checked)
        item->setToolTip(
            tr("Range %1 to %2 %3").arg(shownSignificant(lo, 6), shownSignificant(hi, 6), u));
    table->setHorizontalHeaderItem(column, item);
}

void JobForm::setCell(QTableWidget* table, int row, int column, QDoubleSpinBox* w) {
    w->setFrame(false);
    table->setCellWidget(row, column, w);
}

void JobForm::addRow(QFormLayout* form, const QString& label, QWidget* field, const QString& unit) {
    // The field's own name and unit for screen readers and test automation: inside the row
    // widget it is no longer the label's buddy, and its accessible name was empty.
    field->setAccessibleName(label);
    if (!unit.isEmpty()) field->setAccessibleDescription(unit);
    if (unit.isEmpty()) { // no unit (names, choices): the field takes the whole row
        form->addRow(label, field);
        return;
    }
    auto* row = new QWidget(form->parentWidget());
    auto* h = new QHBoxLayout(row);
    h->setContentsMargins(0, 0, 0, 0);
    h->addWidget(field, 1);
    auto* u = new QLabel(unit, row);
    u->setObjectName("unitLabel");
    u->setMinimumWidth(64);
    h->addWidget(u);
    form->addRow(label, row);
}

void JobForm::commit(const std::string& key, const QString& oldValue, const QString& newValue,
                     const std::function<void(cutcell::Job&)>& change) {
    // A refused change (a level too low) leaves the job as it was: the field shows it again.
    if (!editor_->editKey(key, oldValue, newValue, change))
        QTimer::singleShot(0, this, [this] { reload(); });
}

void JobForm::applyAccess() {
    for (const auto& [key, w] : fields_)
        setLocked(w, editor_->lockReason(key));
    for (JobForm* sub : subForms_)
        sub->applyAccess();
}

void JobForm::reload() {
    loading_ = true;
    for (const auto& b : bindings_) {
        const QSignalBlocker block(b.widget);
        b.load(editor_->job());
    }
    reloadExtra(editor_->job());
    loading_ = false;
}

void JobForm::markIssues() {
    std::map<QWidget*, QStringList> messages;
    QStringList mine;
    for (const auto& [key, w] : fields_)
        messages.emplace(w, QStringList{});
    for (const auto& issue : editor_->issues()) {
        auto [lo, hi] = fields_.equal_range(issue.key);
        if (lo == hi) continue;
        // Named as the form names the field (its label), not by the job file's key.
        const QString text = issueText(issue, lo->second->accessibleName());
        mine << text;
        for (auto it = lo; it != hi; ++it)
            messages[it->second] << text;
    }
    marked_ = 0;
    for (const auto& [w, msgs] : messages) {
        setInvalid(w, !msgs.isEmpty(), msgs.join('\n'));
        if (!msgs.isEmpty()) ++marked_;
    }
    mine.removeDuplicates();
    // The note sits below the page's fields (they are all added by now): above them it pushed
    // the fields down as it came, under the operator's pointer.
    if (layout_->indexOf(issuesLabel_) != layout_->count() - 1) {
        layout_->removeWidget(issuesLabel_);
        layout_->addWidget(issuesLabel_);
    }
    issuesLabel_->setVisible(!mine.isEmpty());
    issuesLabel_->setText(mine.join('\n'));
}

} // namespace CutCell::ui
