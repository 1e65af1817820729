// Scene files as text, for tests that derive variants of a shipped scene: read a file, and
// move or scale everything in it.
#pragma once
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include <doctest/doctest.h>

namespace ps::scenetext {

inline std::string readText(const std::string& path) {
    std::ifstream in(path);
    REQUIRE_MESSAGE(in.good(), "cannot read " << path);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// The scene text with every point p replaced by s * p + t (camera eye and target, corners of
// triangles and quads, sphere centres and radii, point light positions), point light
// intensities multiplied by s^2 (the same irradiance at the scaled distances), and the
// resolution set to res x res. Directions (the camera's up) and everything else stay, so the
// image is the same up to rounding.
inline std::string transformScene(const std::string& text, double s, double t, int res) {
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
            if (k == "pointlight" && tok[i] == "intensity")
                for (size_t c = i + 1; c < i + 4; ++c) tok[c] = num(s * s * std::stod(tok[c]));
        }
        for (size_t i = 0; i < tok.size(); ++i) out << (i ? " " : "") << tok[i];
        out << "\n";
    }
    return out.str();
}

}  // namespace ps::scenetext
