// make test-gallery: a scene page's tools in Debian's chromium, headless: the summary table sorted
// by each column, the plot's names apart from each other and from the points, two mappers compared
// (their difference, the flicker, the zoom, all set from the page's address), and the cards side
// by side at common screen widths.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <sstream>

#include "qemu/accuracy/measure.h"
#include "tests/browser/browser.h"
#include "tests/html.h"
#include "tests/system/system.h"

namespace {

using namespace harness;
using htmltest::Attributes;

std::string gallery_dir() { return build_dir() + "/runs/GalleryTools/gallery"; }

// What the tests read, recorded on <body> once the page has loaded.
const char* STAMP =
    "<script>addEventListener('load', () => {\n"
    "  const b = document.body, style = e => getComputedStyle(e);\n"
    "  b.setAttribute('data-rows', [...document.querySelectorAll('#summary tbody tr')].map(r => r.dataset.card).join(' '));\n"
    "  const names = [...document.querySelectorAll('#plot text.name')].map(t => t.getBBox());\n"
    "  const dots = [...document.querySelectorAll('#plot circle.point')].map(c => c.getBBox());\n"
    "  const hit = (a, c) => a.x < c.x + c.width && c.x < a.x + a.width && a.y < c.y + c.height && c.y < a.y + a.height;\n"
    "  let overlaps = 0;\n"
    "  names.forEach((a, i) => { names.forEach((c, j) => { if (i < j && hit(a, c)) ++overlaps; }); dots.forEach(d => { if (hit(a, d)) ++overlaps; }); });\n"
    "  b.setAttribute('data-overlaps', String(overlaps));\n"
    "  b.setAttribute('data-blend', style(document.getElementById('cmp-diff-b')).mixBlendMode);\n"
    "  b.setAttribute('data-rendering', style(document.getElementById('cmp-a-img')).imageRendering);\n"
    "  b.setAttribute('data-transform', style(document.querySelector('#view-a .zoom')).transform);\n"
    "  b.setAttribute('data-flicker-shown', style(document.querySelector('figure.view-flicker-a')).display);\n"
    "  b.setAttribute('data-flick', style(document.getElementById('cmp-flick-a')).animationName);\n"
    "  const cards = [...document.querySelectorAll('section.card[data-kind=mapper]')].slice(0, 2);\n"
    "  b.setAttribute('data-card-tops', cards.map(c => c.offsetTop).join(','));\n"
    "  b.setAttribute('data-stamped', '1');\n"
    "});</script>\n";

class GalleryTools : public testing::Test {
protected:
    static void SetUpTestSuite() {
        std::filesystem::remove_all(gallery_dir());
        made_ = systest::run_command(build_dir() + "/host/modexlab-gallery --scenes cube --out " + gallery_dir() + " --report " + build_dir() + "/report");
    }
    // <body>'s attributes and the whole DOM, the page loaded at `fragment` in a window `width` wide
    static std::pair<Attributes, std::string> load(const std::string& fragment, int width = 1366) {
        EXPECT_EQ(made_.status, 0) << made_.out;
        const std::string dom = browser::rendered_dom(gallery_dir() + "/cube.html", STAMP, fragment, width);
        std::vector<Attributes> body = htmltest::tags(dom, "body");
        EXPECT_EQ(body.size(), 1u);
        if (body.empty() || !body[0].count("data-stamped")) ADD_FAILURE() << "the page did not finish loading";
        return {body.empty() ? Attributes{} : body[0], dom};
    }
    static systest::ToolRun made_;
};
systest::ToolRun GalleryTools::made_;

TEST_F(GalleryTools, TheSummarySortsByEachColumn) {
    for (const std::string key : {"speed", "max", "mean", "pareto"}) {
        SCOPED_TRACE(key);
        const auto [body, dom] = load("#sort=" + key);
        std::map<std::string, Attributes> rows;  // by card
        for (const Attributes& tr : htmltest::tags(dom, "tr"))
            if (tr.count("data-card")) rows[tr.at("data-card")] = tr;
        std::istringstream order(body.at("data-rows"));
        std::vector<double> values;
        for (std::string card; order >> card;) {
            ASSERT_TRUE(rows.count(card)) << card;
            values.push_back(key == "pareto" ? 1 - std::stod(rows[card].at("data-pareto")) : std::stod(rows[card].at("data-" + key)));
        }
        EXPECT_GE(values.size(), size_t(raster::MAPPER_COUNT)) << "a row a mapper card";
        EXPECT_TRUE(std::is_sorted(values.begin(), values.end())) << body.at("data-rows");
        EXPECT_GE(std::count(values.begin(), values.end(), 0.0), key == "pareto" ? 2 : 0);
    }
}

TEST_F(GalleryTools, ThePlotNamesEveryPointApartOnLogAxes) {
    const auto [body, dom] = load("");
    EXPECT_EQ(body.at("data-overlaps"), "0") << "names over names or points";
    size_t points = 0, names = 0;
    for (const Attributes& c : htmltest::tags(dom, "circle")) points += c.count("data-mapper");
    for (const Attributes& t : htmltest::tags(dom, "text")) names += t.count("data-for");
    EXPECT_GE(points, size_t(raster::MAPPER_COUNT));
    EXPECT_EQ(names, points) << "every point named";
    std::vector<double> ticks;
    for (const Attributes& t : htmltest::tags(dom, "text"))
        if (t.count("class") && t.at("class") == "tick-x") ticks.push_back(std::stod(t.at("data-value")));
    ASSERT_GE(ticks.size(), 2u);
    EXPECT_GT(ticks.front(), 0.0) << "no zero or negative speed";
    for (size_t i = 1; i < ticks.size(); ++i) EXPECT_DOUBLE_EQ(ticks[i], 10 * ticks[i - 1]) << "a decade a tick: a log axis";
}

TEST_F(GalleryTools, TwoMappersAreComparedFlickeredAndZoomedFromTheAddress) {
    const auto [body, dom] = load("#compare=fast-affine,exact&flicker=1&zoom=100,60");
    std::map<std::string, std::string> src;
    for (const Attributes& img : htmltest::tags(dom, "img"))
        if (img.count("id")) src[img.at("id")] = img.at("src");
    EXPECT_EQ(src["cmp-a-img"], "img/cube-fast-affine-frame.png");
    EXPECT_EQ(src["cmp-b-img"], "img/cube-exact-frame.png");
    EXPECT_EQ(src["cmp-diff-a"], src["cmp-a-img"]);
    EXPECT_EQ(src["cmp-diff-b"], src["cmp-b-img"]);
    EXPECT_EQ(src["cmp-ref-a"], "img/cube-reference.png") << "each flickers against the exact picture";
    EXPECT_EQ(body.at("data-blend"), "difference") << "black where the two agree";
    EXPECT_EQ(body.at("data-rendering"), "pixelated") << "no smoothing";
    EXPECT_EQ(body.at("data-transform"), "matrix(4, 0, 0, 4, -484, -244)") << "pixel (100, 60) in the middle, 4 times larger";
    EXPECT_NE(body.at("data-flicker-shown"), "none");
    EXPECT_EQ(body.at("data-flick"), "flick");
    const auto [plain, plain_dom] = load("#compare=fast-affine,exact");
    EXPECT_EQ(plain.at("data-flicker-shown"), "none");
    EXPECT_EQ(plain.at("data-transform"), "none") << "the whole frame";
}

TEST_F(GalleryTools, CardsSitSideBySideAtCommonWidths) {
    for (int width : {1366, 1920}) {
        const auto [body, dom] = load("", width);
        const std::string tops = body.at("data-card-tops");
        const size_t comma = tops.find(',');
        ASSERT_NE(comma, std::string::npos) << tops;
        EXPECT_EQ(tops.substr(0, comma), tops.substr(comma + 1)) << width << " wide: the first two cards on one row";
    }
    const auto [narrow, dom] = load("", 1000);
    const std::string tops = narrow.at("data-card-tops");
    EXPECT_NE(tops.substr(0, tops.find(',')), tops.substr(tops.find(',') + 1)) << "1000 wide: one under the other";
}

}  // namespace
