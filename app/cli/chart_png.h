#pragma once
// The PNG of a line chart (core/sim/line_chart.h), drawn with QPainter on the layout the core's
// SVG uses, so a figure's two files look alike (Qt Svg is not a dependency). Needs a
// QGuiApplication for the fonts: ensureGuiApplication() makes one on the offscreen platform.
#include "core/sim/line_chart.h"

#include <QGuiApplication>

#include <memory>
#include <string>

namespace cutcell::cli {

// A QGuiApplication on the "offscreen" platform (no display needed); null when a Qt
// application exists already.
std::unique_ptr<QGuiApplication> ensureGuiApplication();
// The chart as PNG bytes, width x height pixels; throws std::runtime_error when encoding fails.
std::string chartPng(const LineChart& chart, int width = 900, int height = 480);

} // namespace cutcell::cli
