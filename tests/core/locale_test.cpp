// Number text is locale-independent: under de_DE (decimal comma) every writer of the core still
// writes "57.15" and the JSON reader still reads it. Skipped (not passed) when the locale is
// not installed (tools/setup.sh generates it).
#include "core/common/c_format.h"
#include "core/job/default_job.h"
#include "core/job/job_io.h"
#include "core/machine/machine_registry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <clocale>
#include <regex>

using namespace cutcell;

namespace {

class GermanLocale : public ::testing::Test {
  protected:
    void SetUp() override {
        if (!std::setlocale(LC_ALL, "de_DE.UTF-8")) GTEST_SKIP() << "locale de_DE.UTF-8 missing";
        char buf[16];
        std::snprintf(buf, sizeof buf, "%.2f", 1.5);
        ASSERT_STREQ(buf, "1,50") << "the locale is active";
    }
    void TearDown() override { std::setlocale(LC_ALL, "C"); }
};

} // namespace

TEST_F(GermanLocale, FormatAndParseUseTheDecimalPoint) {
    EXPECT_EQ(formatC("%.3f", 57.15), "57.150");
    EXPECT_EQ(parseDouble("57.15").value_or(0), 57.15);
    EXPECT_FALSE(parseDouble("57,15").has_value());
    const json::Value v = json::parse("{\"r\": 57.15}");
    EXPECT_EQ(v.find("r")->asNumber(), 57.15);
    EXPECT_NE(json::write(v).find("57.15"), std::string::npos);
}

TEST_F(GermanLocale, EveryMachineWritesPointsNotCommas) {
    for (const MachineModule* m : machines()) {
        SCOPED_TRACE(m->id());
        const Job job = m->defaultJob();
        const Job again = parseJob(json::write(jobToJson(job)));
        // The whole job survives its file form under the decimal-comma locale (every machine's
        // own section included).
        EXPECT_EQ(json::write(jobToJson(again)), json::write(jobToJson(job)));
        const MachinePlan plan = m->plan(job, {});
        ASSERT_TRUE(plan.ok()) << plan.outcome.message;
        for (const ExportInfo& e : m->exports()) {
            SCOPED_TRACE(e.id);
            const std::string text = m->exportFile(e.id, job, plan);
            if (e.id.find("csv") != std::string::npos) {
                // CSV: cells are comma-separated; a decimal comma would double the cell count
                // of some rows. Every row has as many cells as the header.
                const size_t header = std::count(text.begin(), text.begin() + text.find('\n'), ',');
                size_t pos = text.find('\n') + 1;
                while (pos < text.size()) {
                    const size_t end = text.find('\n', pos);
                    ASSERT_EQ(std::count(text.begin() + pos, text.begin() + end, ','), header)
                        << text.substr(pos, end - pos);
                    pos = end + 1;
                }
            } else {
                EXPECT_FALSE(std::regex_search(text, std::regex("[0-9],[0-9]")))
                    << text.substr(0, 400);
            }
        }
        std::string report, table;
        if (!m->offlineReport(job, plan, &report, &table).refused()) {
            EXPECT_FALSE(std::regex_search(report, std::regex("[0-9],[0-9]"))) << report;
        }
    }
}
