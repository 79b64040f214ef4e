#pragma once
// Base of the parameter forms: binds editor widgets to Job members under the job's dotted keys
// (the keys validateJob() reports), reloads them when the job is replaced, and marks the
// fields that have issues (red frame, tooltip and a message under the form naming the value,
// the unit and the limit).
//
// Threading contract: GUI thread only.
#include "core/job/field_table.h"
#include "core/job/row_table.h"
#include "ui/forms/job_editor.h"

#include <QWidget>

#include <functional>
#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QSpinBox;
class QTableWidget;
class QVBoxLayout;

namespace CutCell::ui {

class JobForm : public QWidget {
    Q_OBJECT
  public:
    JobForm(JobEditor* editor, QWidget* parent = nullptr);

    // The widget bound to a job key (tests, focus on an issue); nullptr if this form has none.
    QWidget* fieldFor(const std::string& key) const;
    std::vector<std::string> keys() const;
    // Number of fields currently marked invalid.
    int markedCount() const;
    // While the machine moves (ParameterTabs): off by default; a form may keep the fields that
    // can change during a run (the flying saw's queue of lengths) on.
    virtual void setEditingLocked(bool locked) { setEnabled(!locked); }
    // Makes each field read-only whose key the editor's gate refuses (user levels), with the
    // reason in its tooltip, and editable again when the gate lets it through.
    void applyAccess();

  protected:
    using DoubleRef = std::function<double&(cutcell::Job&)>;
    using IntRef = std::function<int&(cutcell::Job&)>;
    using BoolRef = std::function<bool&(cutcell::Job&)>;
    using StringRef = std::function<std::string&(cutcell::Job&)>;

    // A spin box with a wide range: limits are the validator's business, so a bad value can be
    // entered, is marked and explained instead of being clamped silently.
    QDoubleSpinBox* bindDouble(const std::string& key, int decimals, DoubleRef ref);
    QSpinBox* bindInt(const std::string& key, IntRef ref);
    QCheckBox* bindBool(const std::string& key, const QString& text, BoolRef ref);
    QLineEdit* bindString(const std::string& key, StringRef ref);
    QPlainTextEdit* bindText(const std::string& key, StringRef ref);
    // An enum as a combo: `get` maps the job to an index, `set` an index to the job.
    QComboBox* bindChoice(const std::string& key, const QStringList& items,
                          std::function<int(const cutcell::Job&)> get,
                          std::function<void(cutcell::Job&, int)> set);
    // Registers an extra key shown on an existing widget (e.g. a group of fields).
    void alsoMark(const std::string& key, QWidget* w);
    // Another form shown inside this one at `index` of its layout (-1: below its fields; the
    // Cut page's cut chart): its keys count as this page's (fieldFor, keys, markedCount,
    // applyAccess).
    void addSubForm(JobForm* form, int index = -1);

    // Adds "label [field] unit" to a form layout.
    static void addRow(QFormLayout* form, const QString& label, QWidget* field,
                       const QString& unit);
    // A row for one key of a machine section's table (core/job/field_table.h): label, unit and
    // decimals from the table, so the form and the file spell the key alike. spec: the job's
    // section of that machine.
    template <class Spec>
    QWidget* addSectionRow(QFormLayout* form, const cutcell::SectionField<Spec>& f,
                           Spec& (*spec)(cutcell::Job&)) {
        QWidget* w = nullptr;
        if (f.number)
            w = bindDouble(f.key, f.decimals,
                           [f, spec](cutcell::Job& j) -> double& { return f.number(spec(j)); });
        else if (f.integer)
            w = bindInt(f.key, [f, spec](cutcell::Job& j) -> int& { return f.integer(spec(j)); });
        else
            throw std::logic_error(std::string(f.key) + ": a choice has its own row");
        addRow(form, fieldLabel(f.label), w, displayUnit(f.unit));
        return w;
    }
    template <class Spec>
    static const cutcell::SectionField<Spec>&
    sectionField(std::span<const cutcell::SectionField<Spec>> table, const char* key) {
        if (const auto* f = cutcell::findField(table, key)) return *f;
        throw std::logic_error(std::string("no field ") + key + " in the section's table");
    }
    // The columns of a row table (core/job/row_table.h) in `table`, one row per table row: a
    // header "label [unit]" per key (its range as the header's tooltip) and a field per cell
    // with the table's decimals, bound to "<array>[r].<key>". row: the job's row r. As
    // bindDouble's, the fields take any value: one beyond the range is marked, not clamped.
    template <class Row>
    void bindRowTable(QTableWidget* table, std::span<const cutcell::RowField<Row>> fields,
                      const std::string& array, Row& (*row)(cutcell::Job&, size_t)) {
        setColumnCount(table, static_cast<int>(fields.size()));
        for (size_t c = 0; c < fields.size(); ++c) {
            const cutcell::RowField<Row>& f = fields[c];
            setColumnHeader(table, static_cast<int>(c), f.label, f.unit, f.lo, f.hi,
                            f.check != cutcell::FieldCheck::None);
            for (int r = 0; r < rowCount(table); ++r) {
                const auto i = static_cast<size_t>(r);
                QDoubleSpinBox* w =
                    bindDouble(cutcell::rowKey(array, i) + "." + f.key, f.decimals,
                               [number = f.number, row, i](cutcell::Job& j) -> double& {
                                   return number(row(j, i));
                               });
                setCell(table, r, static_cast<int>(c), w);
            }
        }
    }
    // A table's label and unit on screen ("kg m^2" as "kg m²", "1" as nothing).
    static QString fieldLabel(const char* label);
    static QString displayUnit(const char* unit);
    QVBoxLayout* mainLayout() const { return layout_; }
    JobEditor* editor() const { return editor_; }
    bool loading() const { return loading_; }

    // Reloads extra (non-bound) widgets after the job was replaced.
    virtual void reloadExtra(const cutcell::Job&) {}

    // A change of `key` through the editor's gate (JobEditor::editKey); a refused one reloads
    // the fields.
    void commit(const std::string& key, const QString& oldValue, const QString& newValue,
                const std::function<void(cutcell::Job&)>& change);

  private:
    // bindRowTable's Qt calls (the header keeps QTableWidget declared only).
    static void setColumnCount(QTableWidget* table, int n);
    static int rowCount(const QTableWidget* table);
    static void setColumnHeader(QTableWidget* table, int column, const char* label,
                                const char* unit, double lo, double hi, bool checked);
    static void setCell(QTableWidget* table, int row, int column, QDoubleSpinBox* w);

    struct Binding {
        QWidget* widget = nullptr;
        std::function<void(const cutcell::Job&)> load;
    };
    void reload();
    void markIssues();
    void registerField(const std::string& key, QWidget* w);

    JobEditor* editor_;
    QVBoxLayout* layout_;
    QLabel* issuesLabel_;
    std::vector<Binding> bindings_;
    std::multimap<std::string, QWidget*> fields_;
    std::vector<JobForm*> subForms_;
    bool loading_ = false;
    int marked_ = 0;
};

} // namespace CutCell::ui
