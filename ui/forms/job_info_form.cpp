#include "ui/forms/job_info_form.h"

#include <QFormLayout>
#include <QGroupBox>
#include <QLineEdit>
#include <QPlainTextEdit>

namespace CutCell::ui {

using cutcell::Job;

JobInfoForm::JobInfoForm(JobEditor* editor, QWidget* parent) : JobForm(editor, parent) {
    auto* jobBox = new QGroupBox(tr("Job"), this);
    auto* jf = new QFormLayout(jobBox);
    addRow(jf, tr("Name"), bindString("name", [](Job& j) -> std::string& { return j.name; }), {});
    auto* desc = bindText("description", [](Job& j) -> std::string& { return j.description; });
    desc->setMaximumHeight(120);
    jf->addRow(tr("Description"), desc);
    mainLayout()->addWidget(jobBox);
    mainLayout()->addStretch(1);
}

} // namespace CutCell::ui
