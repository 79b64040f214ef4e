// The field tables of the machine sections (core/job/field_table.h), by property: every key of
// a table is written at its own path and read back to the same value; a misspelt key anywhere
// in the section is refused with a hint naming the nearest valid key; a value beyond a table's
// range is reported with the key, the value, the unit and the limit; the section the job
// writer produces holds exactly the table's keys (and "kind").
#include "core/job/drive_fields.h"
#include "core/job/field_table.h"
#include "core/job/job_io.h"
#include "core/job/row_table.h"
#include "core/machine/machine_registry.h"
#include "core/machines/flying_saw/flying_saw_module.h"
#include "core/machines/flying_saw/flying_saw_section.h"
#include "core/machines/pipe_robot/pipe_robot_module.h"
#include "core/machines/pipe_robot/pipe_robot_spec.h"
#include "core/machines/profile_cutter/profile_cutter_module.h"
#include "core/machines/profile_cutter/profile_cutter_section.h"
#include "core/machines/quick_return/quick_return_spec.h"
#include "core/machines/section_steel/section_steel_module.h"
#include "core/machines/section_steel/section_steel_section.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <functional>
#include <map>
#include <set>
#include <string>

namespace cutcell {
namespace {

const json::Value* at(const json::Value& root, const std::string& dotted) {
    const json::Value* v = &root;
    size_t from = 0;
    while (v) {
        const auto dot = dotted.find('.', from);
        v = v->find(dotted.substr(from, dot == std::string::npos ? std::string::npos : dot - from));
        if (dot == std::string::npos) return v;
        from = dot + 1;
    }
    return nullptr;
}

// Every leaf key of a JSON object as dotted paths.
void leaves(const json::Value& v, const std::string& prefix, std::set<std::string>& out) {
    for (const auto& [k, m] : v.asObject()) {
        const std::string key = prefix.empty() ? k : prefix + "." + k;
        if (m.isObject())
            leaves(m, key, out);
        else
            out.insert(key);
    }
}

// One machine section as the tests see it.
template <class Spec> struct Section {
    const char* machine;
    std::span<const SectionField<Spec>> (*fields)();
    Spec (*read)(const json::Value&);
    json::Value (*write)(const Spec&);
    std::vector<JobIssue> (*validate)(const Spec&);
    const Spec& (*of)(const Job&);
    const char* manual = nullptr; // keys below this object are written by hand, not by the table

    Spec defaults() const { return of(findMachine(machine)->defaultJob()); }
    // The fields that exist for s (a round tube has no width).
    bool active(const SectionField<Spec>& f, const Spec& s) const { return !f.when || f.when(s); }
};

template <class Spec> void everyKeyIsWrittenAtItsPathAndReadBack(const Section<Spec>& sec) {
    const Spec spec = sec.defaults();
    const json::Value section = sec.write(spec);
    std::set<std::string> written;
    leaves(section, "", written);
    written.erase("kind");
    std::set<std::string> table;
    for (const auto& f : sec.fields()) {
        EXPECT_TRUE(table.insert(f.key).second) << "key twice in the table: " << f.key;
        EXPECT_TRUE(f.label && *f.label) << f.key;
        if (!sec.active(f, spec) || f.writeCustom) continue;
        EXPECT_NE(at(section, f.key), nullptr) << f.key;
    }
    // The writer writes the table's keys and nothing else (an array's members are its own).
    for (const std::string& k : written) {
        bool inTable = table.count(k) > 0;
        for (const auto& f : sec.fields())
            inTable = inTable || (f.writeCustom && k.rfind(std::string(f.key), 0) == 0);
        inTable = inTable || (sec.manual && k.rfind(std::string(sec.manual) + ".", 0) == 0);
        EXPECT_TRUE(inTable) << "written but not in the table: " << k;
    }

    // Change every number, whole number and switch; the file carries the change back.
    Spec changed = spec;
    int k = 0;
    for (const auto& f : sec.fields()) {
        ++k;
        if (f.number) f.number(changed) = f.number(changed) + 0.125 * k;
        if (f.integer) f.integer(changed) = f.integer(changed) + 1;
        if (f.boolean) f.boolean(changed) = !f.boolean(changed);
    }
    Spec back = sec.read(sec.write(changed));
    for (const auto& f : sec.fields()) {
        if (!sec.active(f, changed)) continue;
        if (f.number) {
            EXPECT_EQ(f.number(back), f.number(changed)) << f.key;
        }
        if (f.integer) {
            EXPECT_EQ(f.integer(back), f.integer(changed)) << f.key;
        }
        if (f.boolean) {
            EXPECT_EQ(f.boolean(back), f.boolean(changed)) << f.key;
        }
    }
    // Every choice, each of its names, back.
    for (const auto& f : sec.fields()) {
        if (!f.setChoice) continue;
        for (int i = 0; i < static_cast<int>(f.choices.size()) && f.choices[i]; ++i) {
            Spec c = spec;
            f.setChoice(c, i);
            EXPECT_EQ(f.getChoice(sec.read(sec.write(c))), i) << f.key << " = " << f.choices[i];
        }
    }
}

json::Value* objectAt(json::Value& root, const std::string& path) {
    json::Value* obj = &root;
    size_t from = 0;
    while (obj && !path.empty()) {
        const auto dot = path.find('.', from);
        const std::string part = path.substr(from, dot == std::string::npos ? dot : dot - from);
        json::Value* next = nullptr;
        for (auto& [name, m] : obj->asObject())
            if (name == part) next = &m;
        obj = next;
        if (dot == std::string::npos) break;
        from = dot + 1;
    }
    return obj;
}

template <class Spec> void aMisspeltKeyIsRefusedWhereverItIs(const Section<Spec>& sec) {
    const Spec spec = sec.defaults();
    for (const auto& f : sec.fields()) {
        if (!sec.active(f, spec)) continue;
        json::Value section = sec.write(spec);
        json::Value* obj = objectAt(section, f.parent());
        ASSERT_NE(obj, nullptr) << f.key;
        const std::string typo = f.leaf() + "x"; // one letter too many, beside the real key
        obj->set(typo, 1.0);
        try {
            sec.read(section);
            ADD_FAILURE() << "accepted " << typo;
        } catch (const JobError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find(typo), std::string::npos) << what;
            EXPECT_NE(what.find("did you mean"), std::string::npos) << what;
        }
    }
}

template <class Spec> void aValueBeyondItsRangeNamesKeyValueUnitAndLimit(const Section<Spec>& sec) {
    for (const auto& f : sec.fields()) {
        Spec s = sec.defaults();
        if (f.check == FieldCheck::None || !sec.active(f, s)) continue;
        const double bad = f.hi * 2 + 1; // beyond the upper limit
        if (f.number) f.number(s) = bad;
        if (f.integer) f.integer(s) = static_cast<int>(std::min(bad, 2e9));
        bool named = false;
        for (const JobIssue& i : sec.validate(s))
            if (i.key == f.key) {
                named = true;
                EXPECT_NE(i.message.find(f.unit), std::string::npos) << i.message;
                EXPECT_NE(i.message.find(num(f.hi)), std::string::npos) << i.message;
            }
        EXPECT_TRUE(named) << f.key << " = " << bad << " was not reported";
    }
}

const Section<QuickReturnSpec> kQuickReturn{
    kQuickReturnId,
    quickReturnFields,
    readQuickReturnSection,
    [](const QuickReturnSpec& s) { return writeQuickReturnSection(s, kQuickReturnId); },
    validateQuickReturn,
    quickReturnSpec};
const Section<FlyingSawSpec> kFlyingSaw{
    kFlyingSawId,
    flyingSawFields,
    readFlyingSawSection,
    [](const FlyingSawSpec& s) { return json::Value(writeFlyingSawSection(s)); },
    checkFlyingSawSpec,
    [](const Job& j) -> const FlyingSawSpec& { return *j.machine_spec.as<FlyingSawSpec>(); }};

const Section<section_steel::SectionSteelSpec> kSectionSteel{
    kSectionSteelId,
    section_steel::sectionSteelFields,
    [](const json::Value& v) {
        SectionReader m(v, "machine");
        m.get("kind");
        section_steel::SectionSteelSpec s = section_steel::readSteelSection(m);
        m.finish();
        return s;
    },
    [](const section_steel::SectionSteelSpec& s) {
        json::Object out{{"kind", kSectionSteelId}};
        section_steel::writeSteelSection(s, out);
        return json::Value(out);
    },
    [](const section_steel::SectionSteelSpec& s) {
        IssueChecker c;
        section_steel::checkSteelSpec(c, s, 0.001);
        return c.issues;
    },
    [](const Job& j) -> const section_steel::SectionSteelSpec& {
        return *j.machine_spec.as<section_steel::SectionSteelSpec>();
    },
    "section"};

// The profile cutter's stepper keys: its table alone (the pipe joint's keys and its other
// branches are read by their own code, core/machine/pipe_joint_section.h and the module).
const Section<ProfileCutterSpec> kProfileCutter{
    kProfileCutterId,
    profileCutterFields,
    [](const json::Value& v) {
        SectionReader m(v, "machine");
        m.get("kind");
        ProfileCutterSpec s;
        readFields(m, profileCutterFields(), s);
        m.finish();
        return s;
    },
    [](const ProfileCutterSpec& s) {
        json::Object out{{"kind", kProfileCutterId}};
        for (auto& [k, v] : writeFields(profileCutterFields(), s))
            out.emplace_back(k, v);
        return json::Value(out);
    },
    [](const ProfileCutterSpec& s) {
        IssueChecker c;
        checkFields(c, profileCutterFields(), s);
        return c.issues;
    },
    [](const Job& j) -> const ProfileCutterSpec& { return profileCutterSpec(j); }};

TEST(SectionFields, ProfileCutterWritesEveryKeyAndReadsItBack) {
    everyKeyIsWrittenAtItsPathAndReadBack(kProfileCutter);
}
TEST(SectionFields, ProfileCutterRefusesAMisspeltKey) {
    aMisspeltKeyIsRefusedWhereverItIs(kProfileCutter);
}
TEST(SectionFields, ProfileCutterNamesAValueBeyondItsRange) {
    aValueBeyondItsRangeNamesKeyValueUnitAndLimit(kProfileCutter);
}
// The hole's position is written only when it is not automatic, and read back so.
TEST(SectionFields, ProfileCutterWritesTheHolePositionOnlyWhenSet) {
    ProfileCutterSpec s = kProfileCutter.defaults();
    s.branch_position_auto = true;
    EXPECT_EQ(at(kProfileCutter.write(s), "profile_cutter.branch_position_mm"), nullptr);
    s.branch_position_auto = false;
    s.branch_position_mm = 321.5;
    const json::Value w = kProfileCutter.write(s);
    ASSERT_NE(at(w, "profile_cutter.branch_position_mm"), nullptr);
    const ProfileCutterSpec back = kProfileCutter.read(w);
    EXPECT_FALSE(back.branch_position_auto);
    EXPECT_EQ(back.branch_position_mm, 321.5);
}

TEST(SectionFields, SectionSteelWritesEveryKeyAndReadsItBack) {
    everyKeyIsWrittenAtItsPathAndReadBack(kSectionSteel);
}
TEST(SectionFields, SectionSteelRefusesAMisspeltKey) {
    aMisspeltKeyIsRefusedWhereverItIs(kSectionSteel);
}
TEST(SectionFields, SectionSteelNamesAValueBeyondItsRange) {
    aValueBeyondItsRangeNamesKeyValueUnitAndLimit(kSectionSteel);
}

TEST(SectionFields, QuickReturnWritesEveryKeyAndReadsItBack) {
    everyKeyIsWrittenAtItsPathAndReadBack(kQuickReturn);
}
TEST(SectionFields, QuickReturnRefusesAMisspeltKey) {
    aMisspeltKeyIsRefusedWhereverItIs(kQuickReturn);
}
TEST(SectionFields, QuickReturnNamesAValueBeyondItsRange) {
    aValueBeyondItsRangeNamesKeyValueUnitAndLimit(kQuickReturn);
}
TEST(SectionFields, FlyingSawWritesEveryKeyAndReadsItBack) {
    everyKeyIsWrittenAtItsPathAndReadBack(kFlyingSaw);
}
TEST(SectionFields, FlyingSawRefusesAMisspeltKey) {
    aMisspeltKeyIsRefusedWhereverItIs(kFlyingSaw);
}
TEST(SectionFields, FlyingSawNamesAValueBeyondItsRange) {
    aValueBeyondItsRangeNamesKeyValueUnitAndLimit(kFlyingSaw);
}
TEST(SectionFields, ARoundTubeHasADiameterAndNoWidth) {
    FlyingSawSpec s = kFlyingSaw.defaults();
    s.shape = TubeShape::Round;
    const json::Value w = writeFlyingSawSection(s);
    EXPECT_NE(at(w, "tube.diameter_mm"), nullptr);
    EXPECT_EQ(at(w, "tube.width_mm"), nullptr);
    json::Value bad = w;
    objectAt(bad, "tube")->set("width_mm", 40.0); // a width on a round tube is refused
    EXPECT_THROW(readFlyingSawSection(bad), JobError);
}

// Row tables (core/job/row_table.h), on a row of their own: a mm with a range, a positive deg
// and an optional s that reads as 2.5 when absent (not as the struct's 7).
struct TestRow {
    double a = 0, b = 0, c = 7;
};
// clang-format off
const RowField<TestRow> kTestRow[] = {
    {.key = "a_mm", .unit = "mm", .label = "a", .lo = 0, .hi = 10, .check = FieldCheck::Range,
     .number = [](TestRow& r) -> double& { return r.a; }},
    {.key = "b_deg", .unit = "deg", .label = "b", .lo = 1, .hi = 5, .check = FieldCheck::Positive,
     .number = [](TestRow& r) -> double& { return r.b; }},
    {.key = "c_s", .unit = "s", .label = "c", .number = [](TestRow& r) -> double& { return r.c; },
     .absent = 2.5},
};
// clang-format on
const std::span<const RowField<TestRow>> kTestRows = kTestRow;

std::array<TestRow, 2> readTestRows(const std::string& text) {
    const json::Value v = json::parse(text);
    SectionReader m(v, "machine");
    std::array<TestRow, 2> out{};
    readRows(requiredRows(m, "rows", 2, "two test rows"), m.key("rows"), kTestRows,
             std::span<TestRow>(out));
    m.finish();
    return out;
}

std::string jobError(const std::function<void()>& f) {
    try {
        f();
    } catch (const JobError& e) {
        return e.what();
    }
    return "(accepted)";
}

TEST(RowFields, ReadEveryRowWithTheDefaultOfAnAbsentKey) {
    const auto rows = readTestRows(R"({"rows": [{"a_mm": 1, "b_deg": 2},
                                                {"c_s": 5, "b_deg": 4, "a_mm": 3}]})");
    EXPECT_EQ(rows[0].a, 1);
    EXPECT_EQ(rows[0].b, 2);
    EXPECT_EQ(rows[0].c, 2.5); // absent: the table's value, not the struct's
    EXPECT_EQ(rows[1].a, 3);
    EXPECT_EQ(rows[1].b, 4);
    EXPECT_EQ(rows[1].c, 5);
}

TEST(RowFields, WriteEveryRowInTableOrder) {
    const std::array<TestRow, 2> rows{{{1, 2, 3}, {4, 5, 6}}};
    EXPECT_EQ(json::write(writeRows<TestRow>(kTestRows, rows), 0),
              json::write(json::parse(R"([{"a_mm": 1, "b_deg": 2, "c_s": 3},
                                          {"a_mm": 4, "b_deg": 5, "c_s": 6}])"),
                          0));
    // ... and read back as written.
    const json::Value written = json::Object{{"rows", writeRows<TestRow>(kTestRows, rows)}};
    const auto back = readTestRows(json::write(written));
    EXPECT_EQ(back[1].c, 6);
    EXPECT_EQ(back[0].b, 2);
}

TEST(RowFields, RefuseAnUnknownKeyInARowWithItsHint) {
    // An optional key's typo beside the required ones: refused, named with its row.
    std::string what = jobError([] {
        readTestRows(R"({"rows": [{"a_mm": 1, "b_deg": 2}, {"a_mm": 1, "b_deg": 2, "c_ss": 2}]})");
    });
    EXPECT_EQ(what, "unknown key \"machine.rows[1].c_ss\" (did you mean \"machine.rows[1].c_s\"?)");
    // A required key's typo: the key is missing, its look-alike named.
    what = jobError(
        [] { readTestRows(R"({"rows": [{"a_mm": 1, "b_dge": 2}, {"a_mm": 1, "b_deg": 2}]})"); });
    EXPECT_NE(what.find("machine.rows[0].b_deg"), std::string::npos) << what;
    EXPECT_NE(what.find("found \"machine.rows[0].b_dge\" (misspelt?)"), std::string::npos) << what;
}

TEST(RowFields, NameAMissingKeyAndAWrongShape) {
    EXPECT_NE(jobError([] {
                  readTestRows(R"({"rows": [{"a_mm": 1, "b_deg": 2}, {"b_deg": 2}]})");
              }).find("missing required key machine.rows[1].a_mm (a number in mm)"),
              std::string::npos);
    EXPECT_EQ(jobError([] { readTestRows(R"({"rows": [{"a_mm": 1, "b_deg": 2}]})"); }),
              "machine.rows has 1 rows; it needs 2 (two test rows)");
    EXPECT_EQ(jobError([] { readTestRows(R"({"rows": 3})"); }),
              "machine.rows must be an array of 2 rows (two test rows), found number");
    EXPECT_EQ(jobError([] { readTestRows("{}"); }),
              "missing required key machine.rows (2 rows: two test rows)");
}

TEST(RowFields, RangeCheckNamesTheKeyPathValueUnitAndLimit) {
    const std::array<TestRow, 3> rows{{{1, 2, 3}, {11, 2, 3}, {1, 0, 1e9}}};
    IssueChecker c;
    checkRows<TestRow>(c, kTestRows, "robot.rows", rows);
    ASSERT_EQ(c.issues.size(), 2u); // c_s has no check
    EXPECT_EQ(c.issues[0].key, "robot.rows[1].a_mm");
    EXPECT_EQ(c.issues[0].message, "robot.rows[1].a_mm = 11 mm is outside [0, 10] mm");
    EXPECT_EQ(c.issues[1].key, "robot.rows[2].b_deg");
    EXPECT_EQ(c.issues[1].message, "robot.rows[2].b_deg = 0 deg is outside [1, 5] deg");
}

// The pipe robot's arrays through its module: every key of its row tables is written, in table
// order; a value beyond a table's range is named with its row; a misspelt key is refused.
struct RobotArray {
    const char* key; // dotted below machine
    std::vector<std::string> keys;
};
template <class Row> std::vector<std::string> keysOf(std::span<const RowField<Row>> t) {
    std::vector<std::string> out;
    for (const auto& f : t)
        out.push_back(f.key);
    return out;
}

const json::Value& robotArray(const json::Value& section, const std::string& key) {
    const json::Value* v = at(section, key);
    if (!v || !v->isArray()) throw std::runtime_error("no array " + key);
    return *v;
}

TEST(RowFields, TheRobotWritesItsRowsInTableOrder) {
    const MachineModule* robot = findMachine(kPipeRobotId);
    ASSERT_NE(robot, nullptr);
    const json::Value section = robot->writeSection(robot->defaultJob());
    const RobotArray arrays[] = {{"robot.dh", keysOf(dhRowFields())},
                                 {"controller", keysOf(pidGainFields())},
                                 {"plant", keysOf(jointPlantFields())}};
    for (const auto& a : arrays) {
        const json::Value& rows = robotArray(section, a.key);
        ASSERT_EQ(rows.asArray().size(), static_cast<size_t>(kAxisCount)) << a.key;
        for (const json::Value& row : rows.asArray()) {
            std::vector<std::string> written;
            for (const auto& [k, v] : row.asObject())
                written.push_back(k);
            EXPECT_EQ(written, a.keys) << a.key;
        }
    }
    EXPECT_EQ(keysOf(dhRowFields()),
              (std::vector<std::string>{"alpha_deg", "a_mm", "d_mm", "theta_offset_deg", "min_deg",
                                        "max_deg"}));
}

TEST(RowFields, TheRobotReadsAnAbsentThetaOffsetAsZeroAndRefusesATypo) {
    const MachineModule* robot = findMachine(kPipeRobotId);
    Job job = robot->defaultJob();
    pipeRobotSpec(job).dh[3].theta_offset_deg = 12;
    json::Value section = json::parse(json::write(robot->writeSection(job)));
    json::Object& row3 = objectAt(section, "robot.dh")->asArray()[3].asObject();
    std::erase_if(row3, [](const auto& m) { return m.first == "theta_offset_deg"; });
    Job back = robot->defaultJob();
    robot->readSection(section, back);
    EXPECT_EQ(pipeRobotSpec(back).dh[3].theta_offset_deg, 0);
    EXPECT_EQ(pipeRobotSpec(back).dh[3].a_mm, pipeRobotSpec(job).dh[3].a_mm);

    row3.emplace_back("a_mn", 1.0);
    const std::string what = jobError([&] { robot->readSection(section, back); });
    EXPECT_NE(what.find("unknown key \"machine.robot.dh[3].a_mn\" (did you mean "
                        "\"machine.robot.dh[3].a_mm\"?)"),
              std::string::npos)
        << what;
}

TEST(RowFields, TheRobotNamesARowValueBeyondItsRange) {
    const MachineModule* robot = findMachine(kPipeRobotId);
    Job job = robot->defaultJob();
    pipeRobotSpec(job).dh[2].a_mm = 6000;
    pipeRobotSpec(job).controller[4].kd = -1;
    pipeRobotSpec(job).plant[1].torque_limit_nm = 0;
    std::map<std::string, std::string> found;
    for (const JobIssue& i : robot->validate(job))
        found[i.key] = i.message;
    EXPECT_EQ(found["robot.dh[2].a_mm"], "robot.dh[2].a_mm = 6000 mm is outside [-5000, 5000] mm");
    EXPECT_EQ(found["controller[4].kd_nm_s_per_rad"],
              "controller[4].kd_nm_s_per_rad = -1 N m s/rad is outside [0, 100000] N m s/rad");
    EXPECT_EQ(found["plant[1].torque_limit_nm"],
              "plant[1].torque_limit_nm = 0 N m is outside [0.001, 100000] N m");
}

} // namespace
} // namespace cutcell
