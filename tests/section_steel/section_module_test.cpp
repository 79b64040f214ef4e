// The section-steel module: registry, job round trip (write -> read -> write), each refusal
// naming the key, validation messages (key, value, unit, limit), plan and program.
#include "core/job/job_io.h"
#include "core/machine/machine_registry.h"
#include "core/machines/section_steel/section_steel_module.h"
#include "core/machines/section_steel/section_steel_planner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace cutcell;

namespace {

const MachineModule& steel() {
    const MachineModule* m = findMachine(kSectionSteelId);
    if (!m) throw std::runtime_error("not registered");
    return *m;
}

std::string defaultText() {
    return json::write(jobToJson(steel().defaultJob()));
}

// Edits the default job's JSON and expects parseJob to refuse it with `needle` in the message.
void expectRefused(const std::function<void(json::Object&)>& edit, const std::string& needle) {
    json::Value doc = json::parse(defaultText());
    for (auto& [k, v] : doc.asObject())
        if (k == "machine") edit(v.asObject());
    try {
        parseJob(json::write(doc));
        FAIL() << "accepted; expected: " << needle;
    } catch (const JobError& e) {
        EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
}

json::Value& member(json::Object& o, const std::string& k) {
    for (auto& [key, v] : o)
        if (key == k) return v;
    throw std::runtime_error("no member " + k);
}

} // namespace

TEST(SectionSteelModule, RegisteredWithEightPositionAxes) {
    const auto axes = steel().axes(steel().defaultJob());
    ASSERT_EQ(axes.size(), 8u);
    for (const auto& a : axes)
        EXPECT_EQ(a.mode, CommandMode::Position);
}

TEST(SectionSteelModule, JobRoundTrip) {
    const std::string a = defaultText();
    const Job job = parseJob(a);
    EXPECT_EQ(job.machine, kSectionSteelId);
    EXPECT_EQ(json::write(jobToJson(job)), a);
    EXPECT_TRUE(steel().validate(job).empty());
    // User-defined dimensions round-trip too.
    json::Value doc = json::parse(a);
    for (auto& [k, v] : doc.asObject())
        if (k == "machine")
            member(v.asObject(), "section") =
                json::Object{{"family", "U"}, {"h_mm", 250.0}, {"b_mm", 80.0},       {"tw_mm", 8.0},
                             {"tf_mm", 12.0}, {"r_mm", 12.0},  {"length_mm", 1000.0}};
    const std::string b = json::write(doc);
    EXPECT_EQ(json::write(jobToJson(parseJob(b))), b);
}

TEST(SectionSteelModule, Refusals) {
    expectRefused([](json::Object& m) { m.emplace_back("mitre_deg", 3.0); }, "mitre_deg");
    expectRefused(
        [](json::Object& m) {
            member(m, "section") = json::Object{{"designation", "IPE 301"}};
        },
        "machine.section.designation = \"IPE 301\" is not in the catalogue");
    expectRefused(
        [](json::Object& m) {
            auto& f = member(member(m, "end_cut").asObject(), "flanges").asObject();
            member(f, "groove") = "X";
        },
        "machine.end_cut.flanges.groove = \"X\" is not one of");
    expectRefused(
        [](json::Object& m) {
            member(m, "park_deg") = json::Array{1.0, 2.0};
        },
        "machine.park_deg must be an array of 8 numbers");
    expectRefused([](json::Object& m) { member(m, "drives") = json::Array{}; },
                  "machine.drives must be an array of 8 rows");
}

TEST(SectionSteelModule, ValidationNamesKeyValueUnitLimit) {
    Job job = steel().defaultJob();
    auto* s = job.machine_spec.as<section_steel::SectionSteelSpec>();
    s->cut.mitre_vertical_deg = 60;
    s->cut.web = {section_steel::GrooveType::V, 70, 0};
    s->park_deg[3] = 500;
    const auto issues = steel().validate(job);
    auto has = [&](const std::string& t) {
        for (const auto& i : issues)
            if (i.message.find(t) != std::string::npos) return true;
        return false;
    };
    EXPECT_TRUE(has("end_cut.mitre_vertical_deg = 60 deg is outside [-45, 45] deg"));
    EXPECT_TRUE(has("end_cut.web.angle_deg = 70 deg is outside [5, 60] deg"));
    EXPECT_TRUE(has("park_deg[3] = 500 deg is outside groove_arm.limits_deg[0]"));
}

TEST(SectionSteelModule, DefaultJobPlansAJointSplineForEightAxes) {
    const Job job = steel().defaultJob();
    const MachinePlan plan = steel().plan(job, {});
    ASSERT_TRUE(plan.ok()) << plan.outcome.message;
    ASSERT_TRUE(plan.program);
    EXPECT_EQ(plan.program->axis_count, 8);
    EXPECT_EQ(plan.program->source_kind, MotionSourceKind::JointSpline);
    // The spline starts and ends at rest and stays within the joint limits.
    const auto& sp = plan.program->spline;
    EXPECT_LT(sp.evaluate(0).qd.norm(), 1e-9);
    EXPECT_LT(sp.evaluate(sp.duration()).qd.norm(), 1e-9);
    for (double t = 0; t <= sp.duration(); t += 0.05) {
        const JointVector q = sp.evaluate(t).q;
        for (int i = 0; i < 8; ++i) {
            EXPECT_GE(q[i], plan.program->min_position[i] - 1e-6) << "axis " << i << " t " << t;
            EXPECT_LE(q[i], plan.program->max_position[i] + 1e-6) << "axis " << i << " t " << t;
        }
    }
    const std::string csv = steel().exportFile("path_csv", job, plan);
    EXPECT_NE(csv.find("\nsquare,0,"), std::string::npos);
    EXPECT_EQ(csv.find("nan"), std::string::npos);
}

// A K groove on the flanges cannot bevel the face that lies on the conveyor: the plan says so
// (never silently one-sided), and says nothing of it for other grooves.
TEST(SectionSteelModule, KGrooveOnFlangesSaysTheUndersideIsNotBevelled) {
    Job job = steel().defaultJob();
    auto* spec = job.machine_spec.as<section_steel::SectionSteelSpec>();
    ASSERT_TRUE(spec);
    spec->cut.flanges = {section_steel::GrooveType::K, 30, 2};
    const MachinePlan k = steel().plan(job, {});
    EXPECT_NE(k.summary.find("underside of the bottom flange"), std::string::npos) << k.summary;
    spec->cut.flanges = {section_steel::GrooveType::V, 30, 0};
    const MachinePlan v = steel().plan(job, {});
    EXPECT_EQ(v.summary.find("underside"), std::string::npos) << v.summary;
}
