#include "core/machines/profile_cutter/template_pdf.h"
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

std::string templatePdf(const TemplateDrawing& d) {
    const double W = d.width_mm * kPtPerMm, H = d.height_mm * kPtPerMm;
    if (W > kMaxPagePt || H > kMaxPagePt) {
        char msg[256];
        snprintfC(msg, sizeof msg,
                  "the template is %.0f x %.0f mm; a PDF page can be at most 5080 mm a side",
                  d.width_mm, d.height_mm);
        throw std::runtime_error(msg);
    }
    auto X = [](double mm) { return mm * kPtPerMm; };
    auto Y = [&](double mm) { return H - mm * kPtPerMm; };

    std::string content = "1 J 1 j 0 0 0 RG 0 0 0 rg\n";
    char buf[256];
    for (const auto& l : d.lines) {
        snprintfC(buf, sizeof buf, "%.4f w\n", X(l.width_mm));
        content += buf;
        for (size_t i = 0; i < l.points.size(); ++i) {
            snprintfC(buf, sizeof buf, "%.4f %.4f %s\n", X(l.points[i].x()), Y(l.points[i].y()),
                      i == 0 ? "m" : "l");
            content += buf;
        }
        content += l.closed ? "s\n" : "S\n";
    }
    for (const auto& t : d.texts) {
        const double size = X(t.size_mm);
        const double x = X(t.pos.x()) - (t.centred ? helveticaWidth(t.text, size) / 2 : 0);
        snprintfC(buf, sizeof buf, "BT /F1 %.3f Tf %.4f %.4f Td ", size, x, Y(t.pos.y()));
        content += buf + pdfString(t.text) + " Tj ET\n";
    }

    std::string out = "%PDF-1.4\n%\xE2\xE3\xCF\xD3\n";
    std::vector<size_t> offsets;
    auto object = [&](const std::string& body) {
        offsets.push_back(out.size());
        out += std::to_string(offsets.size()) + " 0 obj\n" + body + "\nendobj\n";
    };
    object("<< /Type /Catalog /Pages 2 0 R >>");
    object("<< /Type /Pages /Kids [3 0 R] /Count 1 >>");
    snprintfC(buf, sizeof buf,
              "<< /Type /Page /Parent 2 0 R /MediaBox [0 0 %.4f %.4f] /Contents 4 0 R "
              "/Resources << /Font << /F1 5 0 R >> >> >>",
              W, H);
    object(buf);
    object("<< /Length " + std::to_string(content.size()) + " >>\nstream\n" + content +
           "endstream");
    object("<< /Type /Font /Subtype /Type1 /BaseFont /Helvetica /Encoding /WinAnsiEncoding >>");
    object("<< /Producer (CutCell) /Title " + pdfString("Cutting template") + " >>");

    const size_t xref = out.size();
    out += "xref\n0 " + std::to_string(offsets.size() + 1) + "\n0000000000 65535 f \n";
    for (size_t off : offsets) {
        snprintfC(buf, sizeof buf, "%010zu 00000 n \n", off);
        out += buf;
    }
    out += "trailer\n<< /Size " + std::to_string(offsets.size() + 1) +
           " /Root 1 0 R /Info 6 0 R >>\nstartxref\n" + std::to_string(xref) + "\n%%EOF\n";
    return out;
}

} // namespace cutcell
