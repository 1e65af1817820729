// Scene files as text (scene_text.h).
#include "scene_text.h"
#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>
#include <doctest/doctest.h>

namespace ps::scenetext {

std::string readText(const std::string& path) {
    std::ifstream in(path);
    REQUIRE_MESSAGE(in.good(), "cannot read " << path);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::string transformScene(const std::string& text, double s, double t, int res) {
    auto num = [](double v) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.9g", v);
        return std::string(buf);
    };
    std::istringstream in(text);
    std::ostringstream out;
    std::string line;
    auto point = [&](std::vector<std::string>& tok, size_t i) {
        for (size_t k = i; k < i + 3; ++k) tok[k] = num(s * std::stod(tok[k]) + t);
    };
    while (std::getline(in, line)) {
        const std::string code = line.substr(0, line.find('#'));
        std::istringstream ls(code);
        std::vector<std::string> tok;
        for (std::string w; ls >> w;) tok.push_back(w);
        if (tok.empty()) {
            out << line << "\n";
            continue;
        }
        const std::string& k = tok[0];
        size_t first = 1;
        if (k == "triangle" || k == "quad") {
            const size_t corners = k == "triangle" ? 3 : 4;
            for (size_t c = 0; c < corners; ++c) point(tok, 1 + 3 * c);
            first = 1 + 3 * corners;
        }
        for (size_t i = first; i < tok.size(); ++i) {
            if (k == "camera" && (tok[i] == "eye" || tok[i] == "target")) point(tok, i + 1);
            if (k == "camera" && tok[i] == "resolution") tok[i + 1] = tok[i + 2] = std::to_string(res);
            if ((k == "sphere" && tok[i] == "center") || (k == "pointlight" && tok[i] == "position")) point(tok, i + 1);
            if (k == "sphere" && tok[i] == "radius") tok[i + 1] = num(s * std::stod(tok[i + 1]));
            if (k == "camera" && (tok[i] == "lens" || tok[i] == "focus")) tok[i + 1] = num(s * std::stod(tok[i + 1]));
            if (k == "pointlight" && tok[i] == "intensity")
                for (size_t c = i + 1; c < i + 4; ++c) tok[c] = num(s * s * std::stod(tok[c]));
        }
        for (size_t i = 0; i < tok.size(); ++i) out << (i ? " " : "") << tok[i];
        out << "\n";
    }
    return out.str();
}

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
    REQUIRE_MESSAGE(!from.empty(), "replaceAll: nothing to replace");
    size_t n = 0;
    for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
        text.replace(at, from.size(), to);
        ++n;
    }
    REQUIRE_MESSAGE(n > 0, "the scene text has no '" << from << "' to replace");
    return text;
}

std::string replaceLines(const std::string& text, const std::string& keyword, const std::string& line) {
    std::istringstream in(text);
    std::ostringstream out;
    size_t n = 0;
    for (std::string l; std::getline(in, l);) {
        std::istringstream words(l);
        std::string first;
        words >> first;
        if (first == keyword) {
            out << line << "\n";
            ++n;
        } else {
            out << l << "\n";
        }
    }
    REQUIRE_MESSAGE(n > 0, "the scene text has no '" << keyword << "' line to replace");
    return out.str();
}

std::string withResolution(const std::string& text, int width, int height) {
    // "resolution", blanks, digits, blanks, digits: the two numbers are replaced.
    const auto blanks = [&](size_t i) {
        while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
        return i;
    };
    const auto digits = [&](size_t i) {
        while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i;
        return i;
    };
    std::string out;
    size_t done = 0, n = 0;
    for (size_t at = text.find("resolution"); at != std::string::npos; at = text.find("resolution", at + 1)) {
        const size_t a = blanks(at + 10), b = digits(a), c = blanks(b), d = digits(c);
        if (a == at + 10 || b == a || c == b || d == c) continue;
        out += text.substr(done, at - done) + "resolution " + std::to_string(width) + " " + std::to_string(height);
        done = d;
        ++n;
    }
    REQUIRE_MESSAGE(n > 0, "the scene text has no 'resolution W H' to replace");
    return out + text.substr(done);
}

}  // namespace ps::scenetext
