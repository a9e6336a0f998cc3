// make test-gallery: every page of a whole gallery (every demo scene, every mapper, speeds from
// build/report when make bench made one) opened in Debian's chromium, headless: every image loads,
// at its size, and each page shows what it says (its cards are the mappers it lists, every one of
// the registry, auto at its five budgets).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "kernel/core/mapper.h"
#include "qemu/accuracy/measure.h"
#include "qemu/harness/session.h"
#include "qemu/tools/demo_scenes.h"
#include "qemu/tools/trade.h"
#include "tests/browser/browser.h"
#include "tests/html.h"
#include "tests/system/system.h"

namespace {

using namespace harness;
using htmltest::Attributes;

std::string gallery_dir() { return build_dir() + "/runs/GalleryBrowser/gallery"; }

// Stamps each image with its natural size once the page has loaded: added to a copy of the page for
// the browser only.
const char* STAMP =
    "<script>addEventListener('load', () => {\n"
    "  for (const img of document.images) img.setAttribute('data-natural', img.complete ? img.naturalWidth + 'x' + img.naturalHeight : 'incomplete');\n"
    "  document.body.setAttribute('data-stamped', String(document.images.length));\n"
    "});</script>\n";

// The page's DOM as Chromium has it after loading the page and its images.
std::string rendered_dom(const std::string& page) { return browser::rendered_dom(gallery_dir() + "/" + page + ".html", STAMP); }

// The text of the first element opened by `marker` (up to its closing `end`), or "".
std::string element(const std::string& dom, const std::string& marker, const std::string& end) {
    size_t at = dom.find(marker);
    return at == std::string::npos ? std::string() : dom.substr(at, dom.find(end, at) - at);
}

class GalleryBrowser : public testing::TestWithParam<std::string> {
protected:
    static void SetUpTestSuite() {
        std::filesystem::remove_all(gallery_dir());
        std::filesystem::create_directories(gallery_dir());
        made_ = systest::run_command(build_dir() + "/host/modexlab-gallery --out " + gallery_dir() + " --report " + build_dir() + "/report");
    }
    static systest::ToolRun made_;
};
systest::ToolRun GalleryBrowser::made_;

TEST_P(GalleryBrowser, EveryImageLoadsAndThePageShowsWhatItSays) {
    ASSERT_EQ(made_.status, 0) << made_.out;
    const std::string page = GetParam(), dom = rendered_dom(page);
    std::vector<Attributes> body = htmltest::tags(dom, "body");
    ASSERT_EQ(body.size(), 1u) << dom.substr(0, 2000);
    ASSERT_TRUE(body[0].count("data-stamped")) << "the page did not finish loading";
    std::vector<Attributes> images = htmltest::tags(dom, "img");
    EXPECT_EQ(body[0]["data-stamped"], std::to_string(images.size()));
    ASSERT_FALSE(images.empty());
    for (const Attributes& img : images) EXPECT_EQ(img.at("data-natural"), "320x240") << img.at("src") << " did not load";

    if (page == "index") {  // a link and a thumbnail a demo scene
        std::set<std::string> links, want;
        for (const Attributes& a : htmltest::tags(dom, "a")) links.insert(a.at("href"));
        for (const DemoScene& d : demo_scenes()) want.insert(std::string(d.name) + ".html");
        EXPECT_EQ(links, want);
        EXPECT_EQ(images.size(), demo_scenes().size());
        return;
    }
    // the cards: the reference, one a registry mapper, auto at each budget; and the lists say so
    std::multiset<std::string> mappers;
    std::set<std::string> budgets, ids;
    int references = 0;
    for (const Attributes& card : htmltest::tags(dom, "section")) {
        const std::string kind = card.at("data-kind");
        ids.insert(card.at("id"));
        if (kind == "reference") ++references;
        if (kind == "reference") continue;
        const raster::Mapper* m = raster::find_mapper(card.at("data-mapper").c_str());
        ASSERT_NE(m, nullptr) << card.at("data-mapper");
        if (kind == "mapper") mappers.insert(m->name);
        if (kind == "budget") {
            EXPECT_TRUE(m->is_auto) << m->name;
            budgets.insert(card.at("data-budget"));
            EXPECT_EQ(card.at("data-title"), std::string(m->name) + "@" + card.at("data-budget"));
        }
        size_t pictures = 0;  // the frame, its error map, and auto's mapper map
        const std::string section = element(dom, "id=\"" + card.at("id") + "\"", "</section>");
        for (const Attributes& img : htmltest::tags(section, "img")) pictures += img.at("src").find("img/" + page + "-") == 0;
        EXPECT_EQ(pictures, m->is_auto ? 3u : 2u) << card.at("id");
    }
    EXPECT_EQ(references, 1);
    std::multiset<std::string> registry;
    for (int i = 0; i < raster::MAPPER_COUNT; ++i) registry.insert(raster::MAPPERS[i].name);
    EXPECT_EQ(mappers, registry) << "every mapper of the registry, once";
    std::set<std::string> want_budgets;
    for (double e : AUTO_BUDGETS) want_budgets.insert(budget_text(e));
    EXPECT_EQ(budgets, want_budgets);

    struct Listed {
        std::string marker;
        size_t count;
        std::string says;
    };
    for (const Listed& l : {Listed{"class=\"listed\"", mappers.size(), std::to_string(mappers.size()) + " mappers, fastest first"},
                            Listed{"class=\"listed-budgets\"", budgets.size(), "auto at " + std::to_string(budgets.size()) + " budgets"}}) {
        const std::string& marker = l.marker;
        const size_t count = l.count;
        const std::string listed = element(dom, marker, "</p>");
        ASSERT_FALSE(listed.empty()) << marker;
        std::vector<Attributes> p = htmltest::tags("<p " + listed, "p"), links = htmltest::tags(listed, "a");
        EXPECT_EQ(p[0].at("data-count"), std::to_string(count)) << marker;
        EXPECT_NE(listed.find(l.says), std::string::npos) << "says how many: " << listed;
        EXPECT_EQ(links.size(), count) << marker;
        for (const Attributes& a : links) EXPECT_TRUE(ids.count(a.at("href").substr(1))) << a.at("href") << " links to no card";
    }
}

std::vector<std::string> pages() {
    std::vector<std::string> out = {"index"};
    for (const DemoScene& d : demo_scenes()) out.push_back(d.name);
    return out;
}

// (a test's name takes letters, digits and underscores: ball-256's page is the test ending /ball_256)
INSTANTIATE_TEST_SUITE_P(Pages, GalleryBrowser, testing::ValuesIn(pages()), [](const testing::TestParamInfo<std::string>& i) {
    std::string name = i.param;
    for (char& c : name)
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'))) c = '_';
    return name;
});

}  // namespace
