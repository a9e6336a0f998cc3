// Reading the gallery's pages in the tests: the start tags of a kind, with their attributes.
#pragma once

#include <cctype>
#include <map>
#include <string>
#include <vector>

namespace htmltest {

using Attributes = std::map<std::string, std::string>;

inline std::string unescape(const std::string& s) {
    static const std::pair<const char*, char> ENTITIES[] = {{"&amp;", '&'}, {"&quot;", '"'}, {"&lt;", '<'}, {"&gt;", '>'}};
    std::string out;
    for (size_t i = 0; i < s.size(); ++i) {
        bool replaced = false;
        for (const auto& [entity, c] : ENTITIES)
            if (s.compare(i, std::char_traits<char>::length(entity), entity) == 0) {
                out += c, i += std::char_traits<char>::length(entity) - 1, replaced = true;
                break;
            }
        if (!replaced) out += s[i];
    }
    return out;
}

// Every start tag <NAME ...> in the text, in order, with its attributes (double-quoted values, or
// none: "").
inline std::vector<Attributes> tags(const std::string& html, const std::string& name) {
    std::vector<Attributes> out;
    const std::string open = "<" + name;
    for (size_t at = html.find(open); at != std::string::npos; at = html.find(open, at + 1)) {
        size_t i = at + open.size();
        if (i >= html.size() || !(std::isspace(static_cast<unsigned char>(html[i])) || html[i] == '>')) continue;
        Attributes a;
        while (i < html.size() && html[i] != '>') {
            while (i < html.size() && std::isspace(static_cast<unsigned char>(html[i]))) ++i;
            size_t key = i;
            while (i < html.size() && html[i] != '=' && html[i] != '>' && !std::isspace(static_cast<unsigned char>(html[i]))) ++i;
            std::string k = html.substr(key, i - key), v;
            if (i < html.size() && html[i] == '=' && i + 1 < html.size() && html[i + 1] == '"') {
                size_t end = html.find('"', i + 2);
                if (end == std::string::npos) break;
                v = unescape(html.substr(i + 2, end - i - 2));
                i = end + 1;
            }
            if (!k.empty()) a[k] = v;
        }
        out.push_back(a);
    }
    return out;
}

}  // namespace htmltest
