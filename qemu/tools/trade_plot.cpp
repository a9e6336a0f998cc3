// The report's speed-accuracy plots (trade.h, write_plot): a gnuplot script a scene, and target,
// whose axes, margins and labels are placed here so that no name overprints another.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "qemu/lib/error.h"
#include "qemu/tools/trade.h"

namespace harness {

namespace {

constexpr double MARKER = 7;  // a point's marker (pt 7, ps 1.2), pixels each side of its centre

bool overlap(const PlotLabel& a, double left, double bottom, double right, double top) {
    return a.left < right && left < a.right && a.bottom < top && bottom < a.top;
}

// A log axis from below the least value to above the greatest, by whole thirds of a decade.
std::pair<double, double> log_range(double least, double most) {
    return {std::pow(10.0, std::floor(3 * std::log10(least) - 0.5) / 3), std::pow(10.0, std::ceil(3 * std::log10(most) + 0.5) / 3)};
}

}  // namespace

void place_labels(std::vector<PlotLabel>& labels, const PlotArea& area) {
    std::vector<size_t> order(labels.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return labels[a].front > labels[b].front; });
    std::vector<const PlotLabel*> placed;
    for (size_t i : order) {
        PlotLabel& l = labels[i];
        const double w = area.char_width * double(l.text.size()) + 2, h = area.line_height;
        // rings around the point: right, left, above, below and the diagonals, further out each time
        for (int ring = 1; ring <= 12 && !l.placed; ++ring) {
            const double d = 10.0 * ring;
            const double at[][2] = {{d, -h / 2}, {-d - w, -h / 2}, {-w / 2, d}, {-w / 2, -d - h}, {d, d}, {d, -d - h}, {-d - w, d}, {-d - w, -d - h}};
            for (const auto& o : at) {
                const double left = l.x + o[0], bottom = l.y + o[1], right = left + w, top = bottom + h;
                if (left < area.left || right > area.right || bottom < area.bottom || top > area.top) continue;
                bool free = std::none_of(placed.begin(), placed.end(), [&](const PlotLabel* p) { return overlap(*p, left, bottom, right, top); });
                for (const PlotLabel& p : labels)
                    free = free && !(p.x + MARKER > left && p.x - MARKER < right && p.y + MARKER > bottom && p.y - MARKER < top);
                if (!free) continue;
                l.left = left, l.bottom = bottom, l.right = right, l.top = top, l.placed = true, l.leader = ring > 2;
                break;
            }
        }
        if (l.placed) placed.push_back(&l);
    }
}

std::string write_plot(const std::string& dir, const std::string& scene, const std::vector<TradeRow>& rows, const std::string& target) {
    // the speed plotted: icount's drawing instructions a pixel, or the target's drawing cycles
    auto speed = [&](const TradeRow* r) { return target.empty() ? r->draw_per_pixel() : r->per_pixel(r->cycles_on(target).draw); };
    std::vector<const TradeRow*> points = drawing_rows_by_speed(rows, scene);
    std::erase_if(points, [&](const TradeRow* r) { return !(speed(r) > 0); });
    if (points.empty()) return "";
    std::vector<bool> on_front;
    if (target.empty()) {
        for (const TradeRow* r : points) on_front.push_back(r->pareto);
    } else {
        std::stable_sort(points.begin(), points.end(), [&](const TradeRow* a, const TradeRow* b) { return speed(a) < speed(b); });
        std::vector<std::pair<double, double>> measured;
        std::vector<size_t> index;
        for (size_t i = 0; i < points.size(); ++i)
            if (points[i]->draws_everything()) measured.emplace_back(speed(points[i]), points[i]->accuracy.mean_footprint_error), index.push_back(i);
        on_front.assign(points.size(), false);
        for (size_t k : pareto_front(measured)) on_front[index[k]] = true;
    }
    // the picture: 1000 x 640 pixels, the plot area fixed by its margins, both axes logarithmic
    const double width = 1000, height = 640;
    const PlotArea area{90, 64, 970, 589};
    auto error = [](const TradeRow* r) { return std::max(0.001, r->accuracy.mean_footprint_error); };
    double least_x = speed(points[0]), most_x = least_x, least_y = error(points[0]), most_y = least_y;
    for (const TradeRow* r : points)
        least_x = std::min(least_x, speed(r)), most_x = std::max(most_x, speed(r)), least_y = std::min(least_y, error(r)), most_y = std::max(most_y, error(r));
    const auto [x0, x1] = log_range(least_x, most_x);
    const auto [y0, y1] = log_range(least_y, most_y);
    auto px = [&](double x) { return area.left + (std::log(x / x0) / std::log(x1 / x0)) * (area.right - area.left); };
    auto py = [&](double y) { return area.bottom + (std::log(y / y0) / std::log(y1 / y0)) * (area.top - area.bottom); };
    std::vector<PlotLabel> labels;
    for (size_t i = 0; i < points.size(); ++i) {
        PlotLabel l;
        l.x = px(speed(points[i])), l.y = py(error(points[i])), l.text = points[i]->mapper, l.front = on_front[i];
        labels.push_back(l);
    }
    place_labels(labels, area);

    const std::string base = "trade-" + scene + (target.empty() ? "" : "-" + target);
    std::string gp = dir + "/" + base + ".gp", png = dir + "/" + base + ".png";
    std::ofstream out = open_out(gp);
    out << "# gnuplot script written by modexlab-bench: speed against accuracy for scene " << scene << "\n"
        << "set terminal pngcairo size " << width << "," << height << " font ',10'\nset output '" << png << "'\n"
        << "set title '" << scene << ": speed against accuracy ("
        << (target.empty() ? std::string("QEMU icount") : "timing model, " + std::string(target == "486" ? "486" : "Pentium") + ", zero-wait")
        << "; red: the Pareto front and its mappers; hollow: refuses some polygons)'\n"
        << (target.empty() ? "set xlabel 'guest instructions per pixel drawn: setup, walking, inner loop (log scale; lower is faster)'\n"
                           : "set xlabel 'estimated cycles per pixel drawn: setup, walking, inner loop, choosing (log scale; lower is faster)'\n")
        << "set ylabel 'mean footprint error against the reference (log scale; 0 shown as 0.001)'\n"
        << "set logscale xy\nset grid\nunset key\n"
        << "set lmargin at screen " << area.left / width << "\nset rmargin at screen " << area.right / width << "\n"
        << "set bmargin at screen " << area.bottom / height << "\nset tmargin at screen " << area.top / height << "\n"
        << "set xrange [" << x0 << ":" << x1 << "]\nset yrange [" << y0 << ":" << y1 << "]\n";
    std::string unplaced;
    int n = 0;
    for (const PlotLabel& l : labels) {
        if (!l.placed) {
            unplaced += (unplaced.empty() ? "" : ", ") + l.text;
            continue;
        }
        const double mid_y = (l.bottom + l.top) / 2;
        out << "set label " << ++n << " '" << l.text << "' at screen " << (l.left + 1) / width << "," << mid_y / height << " left noenhanced font ',9'"
            << (l.front ? " tc rgb '#c03030'" : "") << " front\n";
        if (l.leader)  // from the box's nearest edge to the point
            out << "set arrow from screen " << std::clamp(l.x, l.left, l.right) / width << "," << std::clamp(l.y, l.bottom, l.top) / height
                << " to screen " << l.x / width << "," << l.y / height << " nohead lc rgb '#a0a0a0' lw 1\n";
    }
    if (!unplaced.empty()) out << "set label " << ++n << " 'no room to name: " << unplaced << "' at screen 0.01,0.02 left noenhanced font ',8'\n";
    auto block = [&](const char* name, auto keep) {
        out << "$" << name << " << EOD\n";
        for (size_t i = 0; i < points.size(); ++i)
            if (keep(i)) out << fixed(speed(points[i]), 3) << " " << fixed(error(points[i]), 4) << "\n";
        out << "EOD\n";
    };
    block("all", [&](size_t i) { return points[i]->draws_everything(); });
    block("partial", [&](size_t i) { return !points[i]->draws_everything(); });
    block("front", [&](size_t i) { return bool(on_front[i]); });
    const bool any_partial = std::any_of(points.begin(), points.end(), [](const TradeRow* r) { return !r->draws_everything(); });
    out << "plot $front using 1:2 with lines lw 2 lc rgb '#c03030' title 'Pareto front', \\\n"
        << "     $all using 1:2 with points pt 7 ps 1.2 lc rgb '#2050a0' title 'mappers'";
    if (any_partial) out << ", \\\n     $partial using 1:2 with points pt 6 ps 1.2 lc rgb '#808080' title 'refuses some polygons'";
    out << "\n";
    out.close();
    if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) return "";
    std::string cmd = "gnuplot '" + gp + "' 2>'" + gp + ".log'";
    if (std::system(cmd.c_str()) != 0) throw HarnessError("gnuplot failed on " + gp + " (see " + gp + ".log)");
    std::filesystem::remove(gp + ".log");
    return png;
}

}  // namespace harness
