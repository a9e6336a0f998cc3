// The report's speed-accuracy plots (trade.h, write_plot): a gnuplot script a scene, and target.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "qemu/lib/error.h"
#include "qemu/tools/trade.h"

namespace harness {

std::string write_plot(const std::string& dir, const std::string& scene, const std::vector<TradeRow>& rows, const std::string& target) {
    // the speed plotted: icount's drawing instructions a pixel, or the target's drawing cycles
    auto speed = [&](const TradeRow* r) { return target.empty() ? r->draw_per_pixel() : r->per_pixel(r->cycles_on(target).draw); };
    std::vector<const TradeRow*> points = drawing_rows_by_speed(rows, scene);
    std::vector<bool> on_front;
    if (target.empty()) {
        for (const TradeRow* r : points) on_front.push_back(r->pareto);
    } else {
        std::erase_if(points, [&](const TradeRow* r) { return r->cycles_on(target).draw == 0; });
        if (points.empty()) return "";
        std::stable_sort(points.begin(), points.end(), [&](const TradeRow* a, const TradeRow* b) { return speed(a) < speed(b); });
        std::vector<std::pair<double, double>> measured;
        std::vector<size_t> index;
        for (size_t i = 0; i < points.size(); ++i)
            if (points[i]->draws_everything()) measured.emplace_back(speed(points[i]), points[i]->accuracy.mean_footprint_error), index.push_back(i);
        on_front.assign(points.size(), false);
        for (size_t k : pareto_front(measured)) on_front[index[k]] = true;
    }
    const std::string base = "trade-" + scene + (target.empty() ? "" : "-" + target);
    std::string gp = dir + "/" + base + ".gp", png = dir + "/" + base + ".png";
    std::ofstream out = open_out(gp);
    out << "# gnuplot script written by modexlab-bench: speed against accuracy for scene " << scene << "\n"
        << "set terminal pngcairo size 1000,640 font ',10'\nset output '" << png << "'\n"
        << "set title '" << scene << ": speed against accuracy ("
        << (target.empty() ? std::string("QEMU icount") : "timing model, " + std::string(target == "486" ? "486" : "Pentium") + ", zero-wait")
        << "; Pareto front joined; hollow: refuses some polygons)'\n"
        << (target.empty() ? "set xlabel 'guest instructions per pixel drawn: setup, walking, inner loop (lower is faster)'\n"
                           : "set xlabel 'estimated cycles per pixel drawn: setup, walking, inner loop, choosing (lower is faster)'\n")
        << "set ylabel 'mean footprint error against the reference (log scale; 0 shown as 0.001)'\n"
        << "set logscale y\nset grid\nset key top right\nset offsets graph 0.02, graph 0.12, graph 0.05, graph 0.05\n";
    // points in speed order; labels alternate above and below so that neighbours do not overprint
    auto block = [&](const char* name, auto keep) {
        out << "$" << name << " << EOD\n";
        int k = 0;
        for (const TradeRow* r : points)
            if (keep(r, k++)) out << fixed(speed(r), 3) << " " << fixed(std::max(0.001, r->accuracy.mean_footprint_error), 4) << " " << r->mapper << "\n";
        out << "EOD\n";
    };
    block("all", [](const TradeRow* r, int) { return r->draws_everything(); });
    block("all_up", [](const TradeRow* r, int k) { return r->draws_everything() && k % 2 == 0; });
    block("all_down", [](const TradeRow* r, int k) { return r->draws_everything() && k % 2 == 1; });
    block("partial", [](const TradeRow* r, int) { return !r->draws_everything(); });
    out << "$front << EOD\n";
    for (size_t i = 0; i < points.size(); ++i)
        if (on_front[i]) out << fixed(speed(points[i]), 3) << " " << fixed(std::max(0.001, points[i]->accuracy.mean_footprint_error), 4) << "\n";
    out << "EOD\n";
    bool any_partial = std::any_of(points.begin(), points.end(), [](const TradeRow* r) { return !r->draws_everything(); });
    out << "plot $front using 1:2 with lines lw 2 lc rgb '#c03030' title 'Pareto front', \\\n"
        << "     $all using 1:2 with points pt 7 ps 1.2 lc rgb '#2050a0' title 'mappers', \\\n"
        << "     $all_up using 1:2:3 with labels offset char 1,char 0.7 left font ',9' notitle, \\\n"
        << "     $all_down using 1:2:3 with labels offset char 1,char -0.7 left font ',9' notitle";
    if (any_partial)
        out << ", \\\n     $partial using 1:2 with points pt 6 ps 1.2 lc rgb '#808080' title 'refuses some polygons', \\\n"
            << "     $partial using 1:2:3 with labels offset char 1,char -0.6 left font ',9' tc rgb '#808080' notitle";
    out << "\n";
    out.close();
    if (points.empty() || std::system("command -v gnuplot >/dev/null 2>&1") != 0) return "";
    std::string cmd = "gnuplot '" + gp + "' 2>'" + gp + ".log'";
    if (std::system(cmd.c_str()) != 0) throw HarnessError("gnuplot failed on " + gp + " (see " + gp + ".log)");
    std::filesystem::remove(gp + ".log");
    return png;
}

}  // namespace harness
