#include "core/pipe_joint/template_svg.h"
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

// withIds: the cut path gets id="cut" (not on tiles: ids are unique in a file).
void appendPaths(std::string& out, const std::vector<TemplateDrawing::Polyline>& lines,
                 bool withIds) {
    char buf[256];
    for (const auto& l : lines) {
        snprintfC(
            buf, sizeof buf,
            "<path class=\"%s\"%s fill=\"none\" stroke=\"black\" stroke-width=\"%.3f\"%s d=\"",
            l.id.c_str(), withIds && l.id == "cut" ? " id=\"cut\"" : "", l.width_mm,
            l.dashed ? " stroke-dasharray=\"2 1.5\"" : "");
        out += buf;
        for (size_t i = 0; i < l.points.size(); ++i) {
            snprintfC(buf, sizeof buf, "%s%.4f %.4f", i == 0 ? "M" : " L", l.points[i].x(),
                      l.points[i].y());
            out += buf;
        }
        out += l.closed ? " Z\"/>\n" : "\"/>\n";
    }
}

void appendTexts(std::string& out, const std::vector<TemplateDrawing::Text>& texts) {
    char buf[256];
    for (const auto& t : texts) {
        snprintfC(buf, sizeof buf,
                  "<text x=\"%.3f\" y=\"%.3f\" font-family=\"Helvetica, Arial, sans-serif\" "
                  "font-size=\"%.3f\"%s>",
                  t.pos.x(), t.pos.y(), t.size_mm, t.centred ? " text-anchor=\"middle\"" : "");
        out += buf;
        out += xmlEscape(t.text) + "</text>\n";
    }
}

// The elements of one page; a clipped page's template goes into a group clipped by clipId.
void appendPage(std::string& out, const TemplateDrawing& d, const std::string& clipId) {
    char buf[256];
    if (d.clipped) {
        snprintfC(buf, sizeof buf,
                  "<clipPath id=\"%s\"><rect x=\"%.3f\" y=\"%.3f\" width=\"%.3f\" "
                  "height=\"%.3f\"/></clipPath>\n<g clip-path=\"url(#%s)\">\n",
                  clipId.c_str(), d.clip.x, d.clip.y, d.clip.w, d.clip.h, clipId.c_str());
        out += buf;
    }
    appendPaths(out, d.lines, !d.clipped);
    appendTexts(out, d.texts);
    if (d.clipped) out += "</g>\n";
    appendPaths(out, d.marks, false);
    appendTexts(out, d.mark_texts);
}

std::string header(double w, double h) {
    char buf[256];
    snprintfC(buf, sizeof buf,
              "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
              "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.3fmm\" height=\"%.3fmm\" "
              "viewBox=\"0 0 %.3f %.3f\">\n",
              w, h, w, h);
    return buf;
}

} // namespace

std::string templateSvg(const TemplateDrawing& d) {
    std::string out = header(d.width_mm, d.height_mm);
    out += "<rect x=\"0\" y=\"0\" width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    appendPage(out, d, "window");
    out += "</svg>\n";
    return out;
}

std::string templateSvg(const TiledTemplate& t) {
    constexpr double kGap = 10; // mm between the pages on the sheet
    const double w = t.cols * t.page_w_mm + (t.cols - 1) * kGap;
    const double h = t.rows * t.page_h_mm + (t.rows - 1) * kGap;
    std::string out = header(w, h);
    out += "<rect x=\"0\" y=\"0\" width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    char buf[256];
    for (const TemplateTile& tile : t.tiles) {
        const std::string id =
            "tile-r" + std::to_string(tile.row + 1) + "-c" + std::to_string(tile.col + 1);
        snprintfC(buf, sizeof buf,
                  "<g id=\"%s\" transform=\"translate(%.3f %.3f)\">\n<rect class=\"paper\" "
                  "x=\"0\" y=\"0\" width=\"%.3f\" height=\"%.3f\" fill=\"none\" "
                  "stroke=\"#999999\" stroke-width=\"0.3\"/>\n",
                  id.c_str(), tile.col * (t.page_w_mm + kGap), tile.row * (t.page_h_mm + kGap),
                  t.page_w_mm, t.page_h_mm);
        out += buf;
        appendPage(out, tile.page, id + "-window");
        out += "</g>\n";
    }
    out += "</svg>\n";
    return out;
}

} // namespace cutcell
