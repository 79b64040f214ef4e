#include "core/machines/profile_cutter/profile_cutter_spec.h"

namespace cutcell {

const ProfileCutterSpec& profileCutterSpec(const Job& job) {
    return readSpec<ProfileCutterSpec>(job.machine_spec, "the profile cutter's");
}

const ProfileCutterSpec& profileCutterSpecOrDefault(const Job& job) {
    static const ProfileCutterSpec defaults;
    const ProfileCutterSpec* s = job.machine_spec.as<ProfileCutterSpec>();
    return s ? *s : defaults;
}

JointExtras jointExtrasOf(const Job& job) {
    const ProfileCutterSpec& s = profileCutterSpecOrDefault(job);
    return {s.other_branches, s.branch_position_auto, s.branch_position_mm};
}

ProfileCutterSpec& profileCutterSpec(Job& job) {
    return editSpec<ProfileCutterSpec>(job.machine_spec, "the profile cutter's");
}

} // namespace cutcell
