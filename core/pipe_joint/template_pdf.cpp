#include "core/pipe_joint/template_pdf.h"
#include "core/common/c_format.h"

#include <cstdio>
#include <stdexcept>
#include <vector>

namespace cutcell {
namespace {

constexpr double kMaxPagePt = 14400; // PDF 1.4 implementation limit: 200 in

std::string pdfString(const std::string& s) {
    std::string out = "(";
    for (char c : s) {
        if (c == '(' || c == ')' || c == '\\') out += '\\';
        out += c;
    }
    return out + ")";
}

// Helvetica advance widths (1/1000 em) for centring short labels; digits and most lowercase
// letters are 556 units wide.
double helveticaWidth(const std::string& s, double size) {
    double w = 0;
    for (char c : s)
        w += c == ' ' || c == '.' ? 278 : c == '-' ? 333 : 556;
    return w * size / 1000;
}

} // namespace

namespace {

void checkSize(const TemplateDrawing& d) {
    const double W = d.width_mm * kPtPerMm, H = d.height_mm * kPtPerMm;
    if (W > kMaxPagePt || H > kMaxPagePt) {
        char msg[256];
        snprintfC(msg, sizeof msg,
                  "the template is %.0f x %.0f mm; a PDF page can be at most 5080 mm a side",
                  d.width_mm, d.height_mm);
        throw std::runtime_error(msg);
    }
}

std::string pageContent(const TemplateDrawing& d) {
    const double H = d.height_mm * kPtPerMm;
    auto X = [](double mm) { return mm * kPtPerMm; };
    auto Y = [&](double mm) { return H - mm * kPtPerMm; };

    std::string content = "1 J 1 j 0 0 0 RG 0 0 0 rg\n";
    char buf[256];
    const auto paths = [&](const std::vector<TemplateDrawing::Polyline>& lines) {
        for (const auto& l : lines) {
            snprintfC(buf, sizeof buf, "%.4f w\n", X(l.width_mm));
            content += buf;
            if (l.dashed) content += "[5.6693 4.2520] 0 d\n"; // 2 mm dash, 1.5 mm gap
            for (size_t i = 0; i < l.points.size(); ++i) {
                snprintfC(buf, sizeof buf, "%.4f %.4f %s\n", X(l.points[i].x()), Y(l.points[i].y()),
                          i == 0 ? "m" : "l");
                content += buf;
            }
            content += l.closed ? "s\n" : "S\n";
            if (l.dashed) content += "[] 0 d\n";
        }
    };
    const auto texts = [&](const std::vector<TemplateDrawing::Text>& list) {
        for (const auto& t : list) {
            const double size = X(t.size_mm);
            const double x = X(t.pos.x()) - (t.centred ? helveticaWidth(t.text, size) / 2 : 0);
            snprintfC(buf, sizeof buf, "BT /F1 %.3f Tf %.4f %.4f Td ", size, x, Y(t.pos.y()));
            content += buf + pdfString(t.text) + " Tj ET\n";
        }
    };
    if (d.clipped) {
        snprintfC(buf, sizeof buf, "q %.4f %.4f %.4f %.4f re W n\n", X(d.clip.x),
                  Y(d.clip.y + d.clip.h), X(d.clip.w), X(d.clip.h));
        content += buf;
    }
    paths(d.lines);
    texts(d.texts);
    if (d.clipped) content += "Q\n";
    paths(d.marks);
    texts(d.mark_texts);
    return content;
}

} // namespace

std::string templatePdf(const TemplateDrawing& d) {
    return templatePdf(std::vector<TemplateDrawing>{d});
}

std::string templatePdf(const std::vector<TemplateDrawing>& pages) {
    if (pages.empty()) throw std::runtime_error("a PDF needs at least one page");
    for (const auto& d : pages)
        checkSize(d);
    // Objects: 1 catalog, 2 page tree, then page + content per page, then font and info (a
    // single page keeps the numbering 3 page, 4 content, 5 font, 6 info).
    const size_t n = pages.size();
    const size_t font = 3 + 2 * n, info = 4 + 2 * n;
    std::string out = "%PDF-1.4\n%\xE2\xE3\xCF\xD3\n";
    std::vector<size_t> offsets;
    auto object = [&](const std::string& body) {
        offsets.push_back(out.size());
        out += std::to_string(offsets.size()) + " 0 obj\n" + body + "\nendobj\n";
    };
    object("<< /Type /Catalog /Pages 2 0 R >>");
    std::string kids;
    for (size_t k = 0; k < n; ++k)
        kids += (k ? " " : "") + std::to_string(3 + 2 * k) + " 0 R";
    object("<< /Type /Pages /Kids [" + kids + "] /Count " + std::to_string(n) + " >>");
    char buf[256];
    for (size_t k = 0; k < n; ++k) {
        const TemplateDrawing& d = pages[k];
        snprintfC(buf, sizeof buf,
                  "<< /Type /Page /Parent 2 0 R /MediaBox [0 0 %.4f %.4f] /Contents %zu 0 R "
                  "/Resources << /Font << /F1 %zu 0 R >> >> >>",
                  d.width_mm * kPtPerMm, d.height_mm * kPtPerMm, 4 + 2 * k, font);
        object(buf);
        const std::string content = pageContent(d);
        object("<< /Length " + std::to_string(content.size()) + " >>\nstream\n" + content +
               "endstream");
    }
    object("<< /Type /Font /Subtype /Type1 /BaseFont /Helvetica /Encoding /WinAnsiEncoding >>");
    object("<< /Producer (CutCell) /Title " + pdfString("Cutting template") + " >>");

    const size_t xref = out.size();
    out += "xref\n0 " + std::to_string(offsets.size() + 1) + "\n0000000000 65535 f \n";
    for (size_t off : offsets) {
        snprintfC(buf, sizeof buf, "%010zu 00000 n \n", off);
        out += buf;
    }
    out += "trailer\n<< /Size " + std::to_string(offsets.size() + 1) + " /Root 1 0 R /Info " +
           std::to_string(info) + " 0 R >>\nstartxref\n" + std::to_string(xref) + "\n%%EOF\n";
    return out;
}

} // namespace cutcell
