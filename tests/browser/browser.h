// The browser tier's one way to look at a page: Debian's chromium, headless, loads a copy of it with
// a script of the test's added at its end, and the DOM as the page then has it comes back.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "qemu/accuracy/measure.h"
#include "tests/system/system.h"

namespace browser {

// The DOM of `page` (a file) after loading it at `fragment` ("" or "#..."), in a window `width` x
// `height`, with `stamp` (a <script> that records what the test asks in attributes) inserted
// before </body>.
inline std::string rendered_dom(const std::string& page, const std::string& stamp, const std::string& fragment = "", int width = 1366,
                                int height = 900) {
    std::string html = harness::read_whole_file(page);
    const size_t body = html.rfind("</body>");
    if (body == std::string::npos) return "no </body> in " + page;
    html.insert(body, stamp);
    const std::filesystem::path path(page);
    const std::string copy = (path.parent_path() / ("browser-" + path.filename().string())).string(), log = copy + ".log";
    {
        std::ofstream out(copy);
        out << html;
    }
    systest::ToolRun r = systest::run_command("{ chromium --headless --disable-gpu --no-sandbox --virtual-time-budget=10000 --window-size=" +
                                              std::to_string(width) + "," + std::to_string(height) +
                                              " --run-all-compositor-stages-before-draw --dump-dom 'file://" +
                                              std::filesystem::absolute(copy).string() + fragment + "' 2>'" + log + "'; }");
    std::filesystem::remove(copy);
    EXPECT_EQ(r.status, 0) << "chromium failed: see " << log;
    return r.out;
}

}  // namespace browser
