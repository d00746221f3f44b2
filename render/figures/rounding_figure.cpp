#include "render/figures/rounding_figure.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "render/domain/domain_labels.hpp"

namespace pw::render {
inline namespace figures {

namespace {

// "12.5 %": a slide to one decimal.
std::string roundingPercentText(float slide) {
    std::ostringstream pct;
    pct << std::round(slide * 10.0f) / 10.0f << " %";
    return pct.str();
}

}  // namespace

std::string roundingRowTitle(Spacing spacing) {
    switch (spacing) {
        case Spacing::Equal:
            return "integer [1..64]";
        case Spacing::FractionalOdd:
            return "fractional_odd [1, 3, ..., 63]";
        case Spacing::FractionalEven:
            return "fractional_even [2, 4, ..., 64]";
        case Spacing::Pow2:
            break;
    }
    return "pow2 [1, 2, 4, ..., 64]";
}

std::string roundingCellText(const RoundingCell& cell) {
    std::string t = std::to_string(cell.segments);
    if (cell.slide >= 0.0f) t += " (" + roundingPercentText(cell.slide) + ")";
    return t;
}

std::vector<std::string> roundingTableLines(const std::vector<RoundingRow>& rows) {
    std::vector<std::vector<std::string>> cells;
    std::vector<std::string> head{"level"};
    if (!rows.empty())
        for (const RoundingCell& c : rows.front().cells) head.push_back(formatLevel(c.level));
    cells.push_back(head);
    for (const RoundingRow& r : rows) {
        std::vector<std::string> line{roundingRowTitle(r.spacing)};
        for (const RoundingCell& c : r.cells) line.push_back(roundingCellText(c));
        cells.push_back(line);
    }
    std::vector<size_t> width(head.size(), 0);
    for (const auto& line : cells)
        for (size_t i = 0; i < line.size() && i < width.size(); ++i) width[i] = std::max(width[i], line[i].size());
    std::vector<std::string> out;
    for (const auto& line : cells) {
        std::string s;
        for (size_t i = 0; i < line.size(); ++i) s += line[i] + std::string(width[i] - line[i].size() + 3, ' ');
        while (!s.empty() && s.back() == ' ') s.pop_back();
        out.push_back(s);
    }
    return out;
}

std::string roundingTableFigure(std::optional<VectorFormat> format, const std::filesystem::path& output, uint32_t width, uint32_t height,
                                const std::vector<RoundingRow>& rows) {
    return cairoFigure(format, output, width, height, [&](cairo_t* cr) {
        const double W = width, H = height;
        cairo_set_source_rgb(cr, 0.97, 0.97, 0.95);  // the slides' light theme
        cairo_paint(cr);
        const size_t columns = rows.empty() ? 1 : rows.front().cells.size() + 1;
        const double margin = std::round(0.05 * std::min(W, H)), titleH = 0.14 * H;
        const double rowH = (H - 2 * margin - titleH) / double(rows.size() + 1);
        const double firstW = 0.32 * (W - 2 * margin), cellW = (W - 2 * margin - firstW) / double(std::max<size_t>(columns - 1, 1));
        const float text = float(std::clamp(rowH * 0.34, 8.0, 64.0));
        TextStyle title{float(titleH * 0.36), {20, 24, 34, 255}};
        cairoText(cr, margin, margin, "A level's segments per partitioning (the two short ones slid, %)", title, 0.0, 0.0);
        const double top = margin + titleH;
        const auto cellX = [&](size_t c) { return c == 0 ? margin : margin + firstW + cellW * double(c - 1); };
        // Header band, row stripes, then the grid lines.
        cairo_set_source_rgb(cr, 0.86, 0.89, 0.94);
        cairo_rectangle(cr, margin, top, W - 2 * margin, rowH);
        cairo_fill(cr);
        cairo_set_source_rgb(cr, 0.55, 0.57, 0.62);
        cairo_set_line_width(cr, 1.0);
        for (size_t r = 0; r <= rows.size() + 1; ++r) {
            cairo_move_to(cr, margin, top + rowH * double(r));
            cairo_line_to(cr, W - margin, top + rowH * double(r));
        }
        for (size_t c = 0; c <= columns; ++c) {
            const double x = c == columns ? W - margin : cellX(c);
            cairo_move_to(cr, x, top);
            cairo_line_to(cr, x, top + rowH * double(rows.size() + 1));
        }
        cairo_stroke(cr);
        const TextStyle head{text, {20, 24, 34, 255}}, body{text, {30, 34, 44, 255}}, slid{float(text * 0.72), {176, 60, 20, 255}};
        const auto centre = [&](size_t r) { return top + rowH * (double(r) + 0.5); };
        cairoText(cr, cellX(0) + 0.3 * text, centre(0), "level", head, 0.0, 0.5);
        if (rows.empty()) return;
        for (size_t c = 0; c < rows.front().cells.size(); ++c)
            cairoText(cr, cellX(c + 1) + 0.5 * cellW, centre(0), formatLevel(rows.front().cells[c].level), head, 0.5, 0.5);
        for (size_t r = 0; r < rows.size(); ++r) {
            const std::string name = roundingRowTitle(rows[r].spacing);
            TextStyle nameStyle = body;  // shrunk to fit its column
            nameStyle.pixels = float(std::min(double(text), text * (firstW - 0.6 * text) / std::max(1.0, cairoTextWidth(cr, name, text))));
            cairoText(cr, cellX(0) + 0.3 * text, centre(r + 1), name, nameStyle, 0.0, 0.5);
            for (size_t c = 0; c < rows[r].cells.size(); ++c) {
                const RoundingCell& cell = rows[r].cells[c];
                const double x = cellX(c + 1) + 0.5 * cellW;
                const bool slide = cell.slide >= 0.0f;
                cairoText(cr, x, centre(r + 1) - (slide ? 0.18 * rowH : 0.0), std::to_string(cell.segments), body, 0.5, 0.5);
                if (slide) cairoText(cr, x, centre(r + 1) + 0.22 * rowH, roundingPercentText(cell.slide), slid, 0.5, 0.5);
            }
        }
    });
}

}  // namespace figures
}  // namespace pw::render
