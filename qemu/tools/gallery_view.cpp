// The gallery page's tools (gallery.h): the summary table, the speed-accuracy plot, the comparison
// of two mappers, and the script and style they share.
#include <algorithm>
#include <cmath>

#include "qemu/tools/gallery.h"
#include "qemu/tools/trade.h"

namespace harness {

namespace {

// The mapper cards that have a speed, and which of them are on the page's Pareto front (speed
// against mean footprint error, among those that draw every polygon).
struct Points {
    std::vector<const GalleryCard*> cards;
    std::vector<bool> front;
};

Points points_of(const GalleryPage& page) {
    Points p;
    for (const GalleryCard& c : page.cards)
        if (c.mapper && c.speed > 0) p.cards.push_back(&c);
    std::vector<std::pair<double, double>> drawn;
    std::vector<size_t> index;
    for (size_t i = 0; i < p.cards.size(); ++i)
        if (p.cards[i]->refused.empty()) drawn.emplace_back(p.cards[i]->speed, p.cards[i]->metrics.mean_footprint_error), index.push_back(i);
    p.front.assign(p.cards.size(), false);
    for (size_t k : pareto_front(drawn)) p.front[index[k]] = true;
    return p;
}

double shown_error(const GalleryCard& c) { return std::max(0.001, c.metrics.mean_footprint_error); }

// "1000", "1", "0.01": a decade's tick.
std::string decade(int k) {
    if (k >= 0) return std::to_string(int(std::lround(std::pow(10.0, k))));
    return "0." + std::string(size_t(-k - 1), '0') + "1";
}

}  // namespace

std::string summary_html(const GalleryPage& page) {
    const Points p = points_of(page);
    std::string s = "<table class=\"summary\" id=\"summary\">\n<thead><tr><th>mapper</th><th data-sort=\"speed\">speed</th>"
                    "<th data-sort=\"max\">max footprint error</th><th data-sort=\"mean\">mean footprint error</th>"
                    "<th data-sort=\"pareto\">Pareto front</th></tr></thead>\n<tbody>\n";
    for (const GalleryCard& c : page.cards) {
        if (!c.mapper) continue;
        const auto at = std::find(p.cards.begin(), p.cards.end(), &c);
        const bool front = at != p.cards.end() && p.front[size_t(at - p.cards.begin())], compared = c.metrics.compared > 0;
        s += "<tr data-card=\"card-" + escape(c.file) + "\" data-speed=\"" + (c.speed > 0 ? fixed(c.speed, 3) : "1e300") + "\" data-max=\"" +
             (compared ? fixed(c.metrics.max_footprint_error, 6) : "1e300") + "\" data-mean=\"" +
             (compared ? fixed(c.metrics.mean_footprint_error, 6) : "1e300") + "\" data-pareto=\"" + (front ? "1" : "0") + "\"><td><a href=\"#card-" +
             escape(c.file) + "\">" + escape(c.title) + "</a>" + (c.refused.empty() ? "" : " (refuses polygons)") + "</td><td class=\"n\">" +
             (c.speed > 0 ? fixed(c.speed, 1) : "-") + "</td><td class=\"n\">" + (compared ? fixed(c.metrics.max_footprint_error, 3) : "-") +
             "</td><td class=\"n\">" + (compared ? fixed(c.metrics.mean_footprint_error, 4) : "-") + "</td><td>" + (front ? "yes" : "") + "</td></tr>\n";
    }
    return s + "</tbody>\n</table>\n";
}

std::string plot_svg(const GalleryPage& page) {
    const Points p = points_of(page);
    if (p.cards.empty()) return "";
    const double height = 640;
    const PlotArea area{90, 64, 970, 589, 7, 14};  // (11-pixel names: a line's glyphs within 14)
    double x_low = p.cards[0]->speed, x_high = x_low, y_low = shown_error(*p.cards[0]), y_high = y_low;
    for (const GalleryCard* c : p.cards)
        x_low = std::min(x_low, c->speed), x_high = std::max(x_high, c->speed), y_low = std::min(y_low, shown_error(*c)), y_high = std::max(y_high, shown_error(*c));
    const int kx0 = int(std::floor(std::log10(x_low))), kx1 = int(std::ceil(std::log10(x_high))) + (x_high == std::pow(10.0, std::ceil(std::log10(x_high))));
    const int ky0 = int(std::floor(std::log10(y_low))), ky1 = int(std::ceil(std::log10(y_high))) + (y_high == std::pow(10.0, std::ceil(std::log10(y_high))));
    const double x_decades = std::max(1, kx1 - kx0), y_decades = std::max(1, ky1 - ky0);
    auto px = [&](double x) { return area.left + (std::log10(x) - kx0) / x_decades * (area.right - area.left); };
    auto py = [&](double y) { return area.bottom + (std::log10(y) - ky0) / y_decades * (area.top - area.bottom); };
    auto down = [&](double y) { return fixed(height - y, 1); };  // SVG's y runs down
    std::vector<PlotLabel> labels;
    for (size_t i = 0; i < p.cards.size(); ++i) {
        PlotLabel l;
        l.x = px(p.cards[i]->speed), l.y = py(shown_error(*p.cards[i])), l.text = p.cards[i]->title, l.front = p.front[i];
        labels.push_back(l);
    }
    place_labels(labels, area);
    std::string s = "<svg class=\"trade\" id=\"plot\" width=\"1000\" height=\"640\" viewBox=\"0 0 1000 640\" "
                    "font-family=\"sans-serif\" font-size=\"11\">\n<rect x=\"0\" y=\"0\" width=\"1000\" height=\"640\" fill=\"#fff\"/>\n";
    for (int k = kx0; k <= kx0 + int(x_decades); ++k)
        s += "<line class=\"grid\" x1=\"" + fixed(px(std::pow(10.0, k)), 1) + "\" y1=\"" + down(area.bottom) + "\" x2=\"" + fixed(px(std::pow(10.0, k)), 1) +
             "\" y2=\"" + down(area.top) + "\" stroke=\"#ddd\"/><text class=\"tick-x\" data-value=\"" + decade(k) + "\" x=\"" + fixed(px(std::pow(10.0, k)), 1) + "\" y=\"" +
             down(area.bottom - 16) + "\" text-anchor=\"middle\">" + decade(k) + "</text>\n";
    for (int k = ky0; k <= ky0 + int(y_decades); ++k)
        s += "<line class=\"grid\" x1=\"" + fixed(area.left, 1) + "\" y1=\"" + down(py(std::pow(10.0, k))) + "\" x2=\"" + fixed(area.right, 1) + "\" y2=\"" +
             down(py(std::pow(10.0, k))) + "\" stroke=\"#ddd\"/><text class=\"tick-y\" x=\"" + fixed(area.left - 6, 1) + "\" y=\"" +
             down(py(std::pow(10.0, k)) - 4) + "\" text-anchor=\"end\">" + decade(k) + "</text>\n";
    s += "<text x=\"530\" y=\"630\" text-anchor=\"middle\">" + escape(page.measured ? "draw instructions per pixel, measured (log scale; lower is faster)"
                                                                                    : "draw instructions per pixel, estimated by the cost model (log scale)") +
         "</text>\n<text x=\"16\" y=\"330\" text-anchor=\"middle\" transform=\"rotate(-90 16 330)\">mean footprint error (log scale; 0 shown as "
         "0.001)</text>\n";
    std::string front;
    for (size_t i = 0; i < p.cards.size(); ++i)
        if (p.front[i]) front += fixed(labels[i].x, 1) + "," + down(labels[i].y) + " ";
    s += "<polyline class=\"front\" points=\"" + front + "\" fill=\"none\" stroke=\"#c03030\" stroke-width=\"2\"/>\n";
    std::string unplaced;
    for (const PlotLabel& l : labels)
        if (!l.placed) unplaced += (unplaced.empty() ? "" : ", ") + l.text;
    if (!unplaced.empty()) s += "<text class=\"no-room\" x=\"8\" y=\"14\">no room to name: " + escape(unplaced) + "</text>\n";
    for (size_t i = 0; i < p.cards.size(); ++i) {
        const PlotLabel& l = labels[i];
        const bool hollow = !p.cards[i]->refused.empty();
        s += "<circle class=\"point\" data-mapper=\"" + escape(l.text) + "\" cx=\"" + fixed(l.x, 1) + "\" cy=\"" + down(l.y) + "\" r=\"5\" fill=\"" +
             (hollow ? "none" : "#2050a0") + "\" stroke=\"" + (hollow ? "#808080" : "#2050a0") + "\"/>\n";
        if (!l.placed) continue;
        if (l.leader)
            s += "<line class=\"leader\" x1=\"" + fixed(std::clamp(l.x, l.left, l.right), 1) + "\" y1=\"" + down(std::clamp(l.y, l.bottom, l.top)) +
                 "\" x2=\"" + fixed(l.x, 1) + "\" y2=\"" + down(l.y) + "\" stroke=\"#aaa\"/>\n";
        s += "<text class=\"name\" data-for=\"" + escape(l.text) + "\" x=\"" + fixed(l.left + 1, 1) + "\" y=\"" + down(l.bottom + 3) + "\"" +
             (l.front ? " fill=\"#c03030\"" : "") + ">" + escape(l.text) + "</text>\n";
    }
    return s + "</svg>\n";
}

std::string compare_html(const GalleryPage& page) {
    std::string options, reference;
    for (const GalleryCard& c : page.cards) {
        if (!c.mapper) {
            reference = image_path(page, c, "");
            continue;
        }
        options += "<option value=\"" + escape(c.file) + "\" data-src=\"" + escape(image_path(page, c, "frame")) + "\">" + escape(c.title) + "</option>";
    }
    auto view = [](const std::string& id, const std::string& images, const std::string& caption) {
        return "<figure class=\"" + id + "\"><div class=\"view\" id=\"" + id + "\"><div class=\"zoom\">" + images + "</div></div><figcaption>" +
               caption + "</figcaption></figure>\n";
    };
    auto img = [](const std::string& id, const std::string& src, const std::string& cls) {
        return "<img id=\"" + id + "\" class=\"" + cls + "\" src=\"" + escape(src) + "\" width=\"640\" height=\"480\" alt=\"\">";
    };
    return "<div class=\"compare\" id=\"compare\">\n<h2>Compare two mappers</h2>\n<p><label>A <select id=\"cmp-a\">" + options +
           "</select></label> <label>B <select id=\"cmp-b\">" + options +
           "</select></label> <label><input type=\"checkbox\" id=\"cmp-flicker\"> flicker each against the exact picture</label> "
           "<button type=\"button\" id=\"cmp-whole\">whole frame</button> Click a picture to look at that region pixel for pixel "
           "(4 times larger, no smoothing). The page's address keeps the choice (#compare=A,B&amp;flicker=1&amp;zoom=X,Y).</p>\n<div class=\"panes\">\n" +
           view("view-a", img("cmp-a-img", reference, "frame"), "A") + view("view-b", img("cmp-b-img", reference, "frame"), "B") +
           view("view-diff", img("cmp-diff-a", reference, "frame") + img("cmp-diff-b", reference, "frame difference"),
                "A against B: black where they agree") +
           view("view-flicker-a", img("cmp-ref-a", reference, "frame") + img("cmp-flick-a", reference, "frame flick"), "A, flickering against the exact picture") +
           view("view-flicker-b", img("cmp-ref-b", reference, "frame") + img("cmp-flick-b", reference, "frame flick"), "B, flickering against the exact picture") +
           "</div>\n</div>\n";
}

const char* const TOOLS_STYLE =
    ".cards{display:grid;grid-template-columns:repeat(auto-fill,minmax(650px,1fr));gap:0 12px}\n"
    "table.summary th[data-sort]{cursor:pointer;text-decoration:underline}\n"
    ".panes{display:flex;flex-wrap:wrap;gap:1em;background:#222;padding:.6em}\n"
    ".view{position:relative;width:640px;height:480px;overflow:hidden;background:#000}\n"
    ".view .zoom{position:absolute;left:0;top:0;width:640px;height:480px;transform-origin:0 0}\n"
    ".view img{position:absolute;left:0;top:0;width:640px;height:480px;image-rendering:pixelated}\n"
    ".view img.difference{mix-blend-mode:difference}\n"
    ".view img.flick{animation:flick 1s steps(1,end) infinite}\n"
    "@keyframes flick{50%{opacity:0}}\n"
    ".compare:not(.flickering) .view-flicker-a,.compare:not(.flickering) .view-flicker-b{display:none}\n";

const char* const PAGE_SCRIPT =
    "<script>\n"
    "(() => {\n"
    "  const state = new URLSearchParams(location.hash.slice(1));\n"
    "  const table = document.getElementById('summary');\n"
    "  const value = (row, key) => key === 'pareto' ? -Number(row.dataset.pareto) * 1e301 + Number(row.dataset.speed) : Number(row.dataset[key]);\n"
    "  const save = () => history.replaceState(null, '', '#' + state.toString());\n"
    "  function sortBy(key) {\n"
    "    const body = table.tBodies[0];\n"
    "    [...body.rows].sort((a, b) => value(a, key) - value(b, key)).forEach(r => body.appendChild(r));\n"
    "    table.dataset.sorted = key;\n"
    "  }\n"
    "  for (const th of table.querySelectorAll('th[data-sort]')) th.onclick = () => { sortBy(th.dataset.sort); state.set('sort', th.dataset.sort); save(); };\n"
    "  if (state.get('sort')) sortBy(state.get('sort'));\n"
    "  const panel = document.getElementById('compare');\n"
    "  const a = document.getElementById('cmp-a'), b = document.getElementById('cmp-b'), flicker = document.getElementById('cmp-flicker');\n"
    "  const [first, second] = (state.get('compare') || '').split(',');\n"
    "  if (first) a.value = first;\n"
    "  if (second) b.value = second; else if (b.options.length > 1) b.selectedIndex = 1;\n"
    "  flicker.checked = state.get('flicker') === '1';\n"
    "  let zoom = (state.get('zoom') || '').split(',').map(Number);\n"
    "  function show() {\n"
    "    const src = s => s.options[s.selectedIndex].dataset.src;\n"
    "    for (const id of ['cmp-a-img', 'cmp-diff-a', 'cmp-flick-a']) document.getElementById(id).src = src(a);\n"
    "    for (const id of ['cmp-b-img', 'cmp-diff-b', 'cmp-flick-b']) document.getElementById(id).src = src(b);\n"
    "    panel.classList.toggle('flickering', flicker.checked);\n"
    "    const zoomed = zoom.length === 2 && zoom.every(Number.isFinite);\n"
    "    for (const z of panel.querySelectorAll('.zoom'))\n"
    "      z.style.transform = zoomed ? `translate(320px, 240px) scale(4) translate(${-2 * zoom[0] - 1}px, ${-2 * zoom[1] - 1}px)` : '';\n"
    "    panel.dataset.zoom = zoomed ? zoom.join(',') : '';\n"
    "    state.set('compare', a.value + ',' + b.value);\n"
    "    if (flicker.checked) state.set('flicker', '1'); else state.delete('flicker');\n"
    "    if (zoomed) state.set('zoom', zoom.join(',')); else state.delete('zoom');\n"
    "  }\n"
    "  a.onchange = b.onchange = flicker.onchange = () => { show(); save(); };\n"
    "  document.getElementById('cmp-whole').onclick = () => { zoom = []; show(); save(); };\n"
    "  for (const v of panel.querySelectorAll('.view'))\n"
    "    v.onclick = e => { if (zoom.length !== 2) { zoom = [Math.floor(e.offsetX / 2), Math.floor(e.offsetY / 2)]; show(); save(); } };\n"
    "  show();\n"
    "})();\n"
    "</script>\n";

}  // namespace harness
