#include "chart_png.h"

#include <QBuffer>
#include <QColor>
#include <QFont>
#include <QImage>
#include <QPainter>
#include <QPainterPath>

#include <clocale>
#include <cmath>
#include <stdexcept>

namespace cutcell::cli {
namespace {

QString text(const std::string& s) {
    return QString::fromStdString(s);
}

QColor color(const std::string& s) {
    return QColor(QString::fromStdString(s));
}

// Text anchored as SVG's text-anchor (start, middle, end) on a baseline at y.
void drawText(QPainter& p, double x, double y, const QString& s, int px, Qt::Alignment a) {
    QFont f = p.font();
    f.setPixelSize(px);
    p.setFont(f);
    const double w = p.fontMetrics().horizontalAdvance(s);
    const double left = a & Qt::AlignHCenter ? x - w / 2 : a & Qt::AlignRight ? x - w : x;
    p.drawText(QPointF(left, y), s);
}

} // namespace

std::unique_ptr<QGuiApplication> ensureGuiApplication() {
    if (QCoreApplication::instance()) return nullptr;
    static int argc = 3;
    static char name[] = "cutcell-cli", opt[] = "-platform", platform[] = "offscreen";
    static char* argv[] = {name, opt, platform, nullptr};
    auto app = std::make_unique<QGuiApplication>(argc, argv);
    std::setlocale(LC_NUMERIC, "C"); // as ensureQCoreApplication (qt_app.h)
    return app;
}

std::string chartPng(const LineChart& chart, int width, int height) {
    const ChartLayout l = chartLayout(chart, width, height);
    QImage img(width, height, QImage::Format_ARGB32);
    img.fill(Qt::white);
    {
        QPainter p(&img);
        p.setRenderHint(QPainter::Antialiasing);
        p.setFont(QFont(QStringLiteral("sans-serif")));
        const QRectF plot(QPointF(l.left, l.top), QPointF(l.right, l.bottom));
        for (const ChartTick& t : l.yticks) {
            const double y = l.py(t.value);
            p.setPen(QPen(QColor(t.value == 0 ? "#999999" : "#e4e4e4"), 1));
            p.drawLine(QPointF(l.left, y), QPointF(l.right, y));
            p.setPen(Qt::black);
            drawText(p, l.left - 6, y + 4, text(t.text), 12, Qt::AlignRight);
        }
        for (const ChartTick& t : l.xticks) {
            const double x = l.px(t.value);
            p.setPen(QPen(QColor("#e4e4e4"), 1));
            p.drawLine(QPointF(x, l.top), QPointF(x, l.bottom));
            p.setPen(Qt::black);
            drawText(p, x, l.bottom + 17, text(t.text), 12, Qt::AlignHCenter);
        }
        p.setPen(QPen(QColor("#444444"), 1));
        p.setBrush(Qt::NoBrush);
        p.drawRect(plot);
        p.save();
        p.setClipRect(plot);
        for (const ChartSeries& c : chart.series) {
            const QColor col = color(c.color);
            p.setPen(QPen(col, 1.5));
            QPainterPath path;
            bool open = false;
            for (size_t i = 0; i < c.x.size() && i < c.y.size(); ++i) {
                if (!std::isfinite(c.x[i]) || !std::isfinite(c.y[i])) {
                    open = false;
                    continue;
                }
                const QPointF pt(l.px(c.x[i]), l.py(c.y[i]));
                if (open)
                    path.lineTo(pt);
                else
                    path.moveTo(pt);
                open = true;
                if (c.markers) {
                    p.save();
                    p.setPen(Qt::NoPen);
                    p.setBrush(col);
                    p.drawEllipse(pt, 4, 4);
                    p.restore();
                }
            }
            p.setBrush(Qt::NoBrush);
            p.drawPath(path);
        }
        p.restore();
        p.setPen(Qt::black);
        drawText(p, (l.left + l.right) / 2, 24, text(chart.title), 16, Qt::AlignHCenter);
        drawText(p, (l.left + l.right) / 2, l.bottom + 42, text(chart.x_label), 13,
                 Qt::AlignHCenter);
        p.save();
        p.translate(18, (l.top + l.bottom) / 2);
        p.rotate(-90);
        drawText(p, 0, 0, text(chart.y_label), 13, Qt::AlignHCenter);
        p.restore();
        const double rowH = 18, boxW = 150;
        const double bx = l.right - boxW - 8, by = l.top + 8;
        p.setPen(QPen(QColor("#bbbbbb"), 1));
        p.setBrush(QColor(255, 255, 255, 217));
        p.drawRect(QRectF(bx, by, boxW, rowH * static_cast<double>(chart.series.size()) + 6));
        for (size_t i = 0; i < chart.series.size(); ++i) {
            const double y = by + 3 + rowH * (static_cast<double>(i) + 0.5);
            p.setPen(QPen(color(chart.series[i].color), 2.5));
            p.drawLine(QPointF(bx + 8, y), QPointF(bx + 32, y));
            p.setPen(Qt::black);
            drawText(p, bx + 40, y + 4, text(chart.series[i].name), 12, Qt::AlignLeft);
        }
    }
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    if (!img.save(&buffer, "PNG")) throw std::runtime_error("cannot encode the PNG");
    return bytes.toStdString();
}

} // namespace cutcell::cli
