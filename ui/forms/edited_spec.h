#pragma once
// The edited job's machine spec, for a machine's form bindings. A machine's form pages exist
// for every job but are shown only for that machine's jobs; for another machine's job the
// bindings read and write a scratch spec of the type (one per type), never the job.
#include "core/job/job.h"

namespace CutCell::ui {

template <class Spec> Spec& editedSpec(cutcell::Job& j) {
    static Spec scratch;
    Spec* s = j.machine_spec.as<Spec>();
    return s ? *s : scratch;
}

// The same for reading: another machine's job reads the spec's defaults.
template <class Spec> const Spec& editedSpec(const cutcell::Job& j) {
    static const Spec defaults;
    const Spec* s = j.machine_spec.as<Spec>();
    return s ? *s : defaults;
}

} // namespace CutCell::ui
