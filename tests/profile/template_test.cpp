// The unrolled cutting template: its geometry, the SVG and the PDF (structure, 1:1 size, render).
#include "core/geometry/pipe_intersection.h"
#include "core/job/job_io.h"
#include "core/machines/profile_cutter/profile_cutter.h"
#include "core/machines/profile_cutter/profile_cutter_spec.h"
#include "core/pipe_joint/template_pdf.h"
#include "core/pipe_joint/template_svg.h"
#include "profile_test_util.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <unistd.h>

namespace cutcell {
namespace {

std::vector<Job> jobs() {
    std::vector<Job> out{test::exampleProfileJob()};
    std::mt19937 rng(77);
    for (int k = 0; k < 6; ++k)
        out.push_back(test::randomProfileJob(rng, k % 2 ? CutTarget::Main : CutTarget::Branch));
    return out;
}

// The points of the path with id="cut" (its d attribute: "Mx y Lx y ... [Z]").
std::vector<Eigen::Vector2d> svgCutPoints(const std::string& svg) {
    std::vector<Eigen::Vector2d> pts;
    const size_t id = svg.find("id=\"cut\"");
    EXPECT_NE(id, std::string::npos);
    const size_t from = svg.find(" d=\"", id) + 4, to = svg.find('"', from);
    std::string d = svg.substr(from, to - from);
    for (char& c : d)
        if (c == 'M' || c == 'L' || c == 'Z') c = ' ';
    std::istringstream in(d);
    double x, y;
    while (in >> x >> y)
        pts.emplace_back(x, y);
    return pts;
}

// The number after `key` in `text` (npos when absent).
double numberAfter(const std::string& text, const std::string& key, size_t* end = nullptr) {
    const size_t at = text.find(key);
    if (at == std::string::npos) return std::nan("");
    size_t used = 0;
    const double v = std::stod(text.substr(at + key.size()), &used);
    if (end) *end = at + key.size() + used;
    return v;
}

// The branch template's curve spans exactly one circumference, and every drawn point is the
// cut's (A, X) developed at 1:1: u = R_w (A - A_low), v = top + y_per_x (X - X_top).
TEST(Template, DevelopedCurveIsTheCutAtFullScale) {
    for (const Job& job : jobs()) {
        const TemplateDrawing d = buildTemplate(job, jointExtrasOf(job), 720);
        const auto pts = svgCutPoints(templateSvg(d));
        const ProfileCut cut = computeProfileCut(job, 720);
        const double C = 2 * kPi * cut.work_radius_mm;
        EXPECT_NEAR(d.circumference_mm, C, 1e-12);
        const size_t expected =
            job.cut.target == CutTarget::Branch ? cut.points.size() + 1 : cut.points.size();
        ASSERT_EQ(pts.size(), expected);
        double umin = 1e300, umax = -1e300;
        for (size_t i = 0; i < pts.size(); ++i) {
            const ProfilePoint p = cut.closedAt(i);
            EXPECT_NEAR(pts[i].x(),
                        d.origin_u_mm + cut.work_radius_mm * deg2rad(p.a_deg - d.a_low_deg), 1e-3);
            EXPECT_NEAR(pts[i].y(), d.top_mm + d.y_per_x * (p.x_mm - d.x_top_mm), 1e-3);
            umin = std::min(umin, pts[i].x());
            umax = std::max(umax, pts[i].x());
        }
        if (job.cut.target == CutTarget::Branch) {
            EXPECT_NEAR(umax - umin, C, 1e-3) << "developed length must be the circumference";
        } else {
            EXPECT_LT(umax - umin, C / 2); // a hole spans less than half a turn
        }
        // The wrap edges are one circumference apart; the page holds the drawing.
        std::vector<double> edges;
        for (const auto& l : d.lines)
            if (l.id == "edge") edges.push_back(l.points[0].x());
        ASSERT_EQ(edges.size(), 2u);
        EXPECT_NEAR(edges[1] - edges[0], C, 1e-9);
        for (const auto& l : d.lines)
            for (const auto& p : l.points) {
                EXPECT_GE(p.x(), 0);
                EXPECT_LE(p.x(), d.width_mm);
                EXPECT_GE(p.y(), 0);
                EXPECT_LE(p.y(), d.height_mm);
            }
    }
}

TEST(Template, SvgIsMillimetreScaled) {
    const TemplateDrawing d =
        buildTemplate(test::exampleProfileJob(), jointExtrasOf(test::exampleProfileJob()));
    const std::string svg = templateSvg(d);
    char expect[128];
    std::snprintf(expect, sizeof expect,
                  "width=\"%.3fmm\" height=\"%.3fmm\" viewBox=\"0 0 %.3f %.3f\"", d.width_mm,
                  d.height_mm, d.width_mm, d.height_mm);
    EXPECT_NE(svg.find(expect), std::string::npos);
    EXPECT_NE(svg.find("100 mm at 1:1"), std::string::npos);
    EXPECT_NE(svg.find(">90 deg<"), std::string::npos);
    EXPECT_EQ(svg.rfind("</svg>\n"), svg.size() - 7);
}

// Structure: every xref offset points at its object, startxref at the table, /Length is exact.
TEST(Template, PdfStructureIsExact) {
    const TemplateDrawing d =
        buildTemplate(test::exampleProfileJob(), jointExtrasOf(test::exampleProfileJob()));
    const std::string pdf = templatePdf(d);
    ASSERT_EQ(pdf.rfind("%PDF-1.4", 0), 0u);
    const size_t tail = pdf.rfind("startxref\n");
    ASSERT_NE(tail, std::string::npos);
    size_t xrefEnd = 0;
    const auto xref = static_cast<size_t>(numberAfter(pdf.substr(tail), "startxref\n", &xrefEnd));
    EXPECT_EQ(pdf.substr(tail + xrefEnd), "\n%%EOF\n");
    ASSERT_EQ(pdf.compare(xref, 5, "xref\n"), 0);
    std::istringstream in(pdf.substr(xref + 5));
    int first = 0, count = 0;
    in >> first >> count;
    ASSERT_EQ(first, 0);
    ASSERT_GE(count, 6);
    std::string line;
    std::getline(in, line);
    std::getline(in, line); // the free entry
    EXPECT_EQ(line, "0000000000 65535 f ");
    for (int obj = 1; obj < count; ++obj) {
        std::getline(in, line);
        ASSERT_EQ(line.size(), 19u) << line; // + '\n' = 20 bytes per entry
        const size_t off = std::stoul(line.substr(0, 10));
        const std::string head = std::to_string(obj) + " 0 obj";
        EXPECT_EQ(pdf.compare(off, head.size(), head), 0) << "object " << obj;
    }
    ASSERT_NE(pdf.find("/Length "), std::string::npos);
    size_t lengthEnd = 0;
    const auto len = static_cast<size_t>(numberAfter(pdf, "/Length ", &lengthEnd));
    ASSERT_EQ(pdf.compare(lengthEnd, 11, " >>\nstream\n"), 0);
    const size_t start = lengthEnd + 11;
    EXPECT_EQ(pdf.compare(start + len, 9, "endstream"), 0);
    // Page size: the template at 72/25.4 pt per mm.
    double w = 0, h = 0;
    const size_t box = pdf.find("/MediaBox [0 0 ");
    ASSERT_NE(box, std::string::npos);
    ASSERT_EQ(std::sscanf(pdf.c_str() + box, "/MediaBox [0 0 %lf %lf]", &w, &h), 2);
    EXPECT_NEAR(w, d.width_mm * kPtPerMm, 1e-3);
    EXPECT_NEAR(h, d.height_mm * kPtPerMm, 1e-3);
    // The cut path is the first path of the content: its width in pt is the circumference.
    const std::string content = pdf.substr(start, len);
    std::istringstream cs(content.substr(content.find(" w\n") + 3));
    double xmin = 1e300, xmax = -1e300, x, y;
    std::string op;
    while (cs >> x >> y >> op && (op == "m" || op == "l")) {
        xmin = std::min(xmin, x);
        xmax = std::max(xmax, x);
    }
    EXPECT_NEAR((xmax - xmin) / kPtPerMm, d.circumference_mm, 1e-3);
}

TEST(Template, TooLargeForAPdfPageIsRefused) {
    TemplateDrawing d =
        buildTemplate(test::exampleProfileJob(), jointExtrasOf(test::exampleProfileJob()));
    d.width_mm = 6000;
    EXPECT_THROW(templatePdf(d), std::runtime_error);
}

// Poppler (Debian's poppler-utils) reads the file, reports the 1:1 page size and renders it.
TEST(Template, PopplerReadsAndRendersThePdf) {
    int status = 0;
    test::runCommand("command -v pdfinfo >/dev/null 2>&1 && command -v pdftoppm >/dev/null 2>&1",
                     &status);
    if (status != 0)
        GTEST_SKIP() << "pdfinfo/pdftoppm (Debian package poppler-utils) are not installed";
    const auto dir =
        std::filesystem::temp_directory_path() / ("cutcell_pdf_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const TemplateDrawing d =
        buildTemplate(test::exampleProfileJob(), jointExtrasOf(test::exampleProfileJob()));
    const std::string file = (dir / "template.pdf").string();
    writeFileAtomically(file, templatePdf(d));
    const std::string info = test::runCommand("pdfinfo " + file + " 2>&1", &status);
    ASSERT_EQ(status, 0) << info;
    double w = 0, h = 0;
    const size_t size = info.find("Page size:");
    ASSERT_NE(size, std::string::npos) << info;
    ASSERT_EQ(std::sscanf(info.c_str() + size, "Page size: %lf x %lf pts", &w, &h), 2) << info;
    EXPECT_NEAR(w / kPtPerMm, d.width_mm, 0.01);
    EXPECT_NEAR(h / kPtPerMm, d.height_mm, 0.01);
    const std::string err = test::runCommand(
        "pdftoppm -r 20 -png " + file + " " + (dir / "page").string() + " 2>&1", &status);
    EXPECT_EQ(status, 0) << err;
    EXPECT_TRUE(err.empty()) << err; // poppler prints syntax warnings here
    EXPECT_GT(std::filesystem::file_size(dir / "page-1.png"), 1000u);
    std::filesystem::remove_all(dir);
}

// The sheet wrapped as it says (printed side out, top edge toward the end it names, the 0 deg
// line on the generator it names, A counter-clockwise seen from that end) lies on the 3D cut:
// every drawn point, wrapped round the pipe, is the cut point (angle and axial position).
TEST(Template, WrappedAsPrintedTheSheetLiesOnTheCut) {
    for (const Job& job : jobs()) {
        const TemplateDrawing d = buildTemplate(job, jointExtrasOf(job), 720);
        const ProfileCut cut = computeProfileCut(job, 720);
        const PipeIntersection pi(profileIntersectionSpec(job));
        const bool branch = job.cut.target == CutTarget::Branch;
        std::string notes;
        for (const auto& t : d.texts)
            notes += t.text + "\n";
        // What the sheet says: the pipe's axis through o, the end the top edge points to
        // (up), the 0 deg generator's outward direction r0.
        Vec3 o, up, r0;
        if (branch) {
            // "top edge toward the end being cut": X (= l) grows toward the main pipe, -b.
            ASSERT_NE(notes.find("top edge toward the end being cut"), std::string::npos);
            // "square to the plane of both pipe axes, on the side a positive eccentricity
            // moves the branch to": main +x.
            ASSERT_NE(notes.find("square to the plane of both"), std::string::npos);
            o = pi.branchOrigin();
            up = -pi.branchAxis();
            r0 = Vec3(1, 0, 0);
        } else {
            // "top edge toward its fixed end (X = 0)": X = S + z, so -z.
            ASSERT_NE(notes.find("top edge toward its fixed end"), std::string::npos);
            // "in line with the branch axis (the crown on the branch side)": main +y.
            ASSERT_NE(notes.find("in line with the branch"), std::string::npos);
            o = Vec3::Zero();
            up = Vec3(0, 0, -1);
            r0 = Vec3(0, 1, 0);
        }
        ASSERT_NE(notes.find("counter-clockwise"), std::string::npos);
        // Printed side out: page right = up x outward normal, i.e. counter-clockwise about up.
        const Vec3 right0 = up.cross(r0);
        const double R = cut.work_radius_mm;
        double axialPlusY = 0;
        for (size_t i = 0; i < cut.points.size(); ++i) {
            const ProfilePoint& p = cut.points[i];
            const double u = d.origin_u_mm + R * deg2rad(p.a_deg - d.a_low_deg);
            const double y = d.top_mm + d.y_per_x * (p.x_mm - d.x_top_mm);
            const double theta = (u - d.zero_u_mm) / R;
            const Vec3 wrapped = std::cos(theta) * r0 + std::sin(theta) * right0;
            const Vec3 rel = p.p_main - o;
            const Vec3 radial = (rel - rel.dot(up) * up).normalized();
            EXPECT_LT((radial - wrapped).norm(), 1e-9) << "point " << i;
            // Up the sheet (smaller page y) is along up on the pipe, mm for mm.
            if (i == 0) axialPlusY = rel.dot(up) + y;
            EXPECT_NEAR(rel.dot(up) + y, axialPlusY, 1e-6) << "point " << i;
        }
    }
}

// The wrap aids are on the sheet: glue tab right of the last edge, 0 deg mark, wrap arrow, the
// pipe OD and circumference, the job name, the scale bar.
TEST(Template, SheetCarriesTabZeroMarkWrapArrowAndPipeData) {
    for (const Job& job : jobs()) {
        const TemplateDrawing d = buildTemplate(job, jointExtrasOf(job), 360);
        const double C = d.circumference_mm;
        std::string text;
        for (const auto& t : d.texts)
            text += t.text + "\n";
        int tabs = 0, zeros = 0, wraps = 0;
        for (const auto& l : d.lines) {
            if (l.id == "tab") {
                ++tabs;
                double xmax = -1e300;
                for (const auto& p : l.points)
                    xmax = std::max(xmax, p.x());
                EXPECT_NEAR(xmax - (d.origin_u_mm + C), d.glue_tab_mm, 1e-9);
            }
            if (l.id == "zero") {
                ++zeros;
                EXPECT_NEAR(l.points[0].x(), d.zero_u_mm, 1e-9);
            }
            wraps += l.id == "wrap";
        }
        EXPECT_EQ(tabs, 1);
        EXPECT_EQ(zeros, 1);
        EXPECT_EQ(wraps, 2); // shaft and head
        EXPECT_GE(d.glue_tab_mm, 10);
        char expect[128];
        std::snprintf(expect, sizeof expect, "glue tab %.0f mm", d.glue_tab_mm);
        EXPECT_NE(text.find(expect), std::string::npos);
        std::snprintf(expect, sizeof expect, "pipe OD %.2f mm, circumference %.2f mm",
                      2 * computeProfileCut(job, 8).work_radius_mm, C);
        EXPECT_NE(text.find(expect), std::string::npos) << text;
        EXPECT_NE(text.find(job.name), std::string::npos);
        EXPECT_NE(text.find(" mm at 1:1"), std::string::npos);
        EXPECT_NEAR(d.zero_u_mm,
                    d.origin_u_mm +
                        computeProfileCut(job, 8).work_radius_mm * deg2rad(0 - d.a_low_deg),
                    1e-9);
    }
}

} // namespace
} // namespace cutcell
