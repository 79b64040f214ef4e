#include "core/machines/profile_cutter/template_svg.h"
#include "core/common/c_format.h"

#include <cstdio>

namespace cutcell {
namespace {

std::string xmlEscape(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

} // namespace

std::string templateSvg(const TemplateDrawing& d) {
    std::string out;
    char buf[256];
    snprintfC(buf, sizeof buf,
              "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
              "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.3fmm\" height=\"%.3fmm\" "
              "viewBox=\"0 0 %.3f %.3f\">\n",
              d.width_mm, d.height_mm, d.width_mm, d.height_mm);
    out += buf;
    out += "<rect x=\"0\" y=\"0\" width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    for (const auto& l : d.lines) {
        snprintfC(buf, sizeof buf,
                  "<path class=\"%s\"%s fill=\"none\" stroke=\"black\" stroke-width=\"%.3f\" d=\"",
                  l.id.c_str(), l.id == "cut" ? " id=\"cut\"" : "", l.width_mm);
        out += buf;
        for (size_t i = 0; i < l.points.size(); ++i) {
            snprintfC(buf, sizeof buf, "%s%.4f %.4f", i == 0 ? "M" : " L", l.points[i].x(),
                      l.points[i].y());
            out += buf;
        }
        out += l.closed ? " Z\"/>\n" : "\"/>\n";
    }
    for (const auto& t : d.texts) {
        snprintfC(buf, sizeof buf,
                  "<text x=\"%.3f\" y=\"%.3f\" font-family=\"Helvetica, Arial, sans-serif\" "
                  "font-size=\"%.3f\"%s>",
                  t.pos.x(), t.pos.y(), t.size_mm, t.centred ? " text-anchor=\"middle\"" : "");
        out += buf;
        out += xmlEscape(t.text) + "</text>\n";
    }
    out += "</svg>\n";
    return out;
}

} // namespace cutcell
