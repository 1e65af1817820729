// For the benchmarks: a scene file loaded with its camera's resolution set to res x res (res > 0;
// otherwise as the file says), so that a benchmark can render any scene small and fast.
#pragma once
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include "scene_loader.h"

namespace bench {

inline ps::Scene loadSceneAt(const std::string& path, int res) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    std::ostringstream s;
    s << in.rdbuf();
    std::string text = s.str();
    const size_t at = text.find("resolution");
    if (res > 0) {
        if (at == std::string::npos) throw std::runtime_error(path + ": no resolution");
        std::istringstream rest(text.substr(at + 10));
        int w = 0, h = 0;
        if (!(rest >> w >> h)) throw std::runtime_error(path + ": bad resolution");
        text.replace(at, 10 + static_cast<size_t>(rest.tellg()),
                     "resolution " + std::to_string(res) + " " + std::to_string(res));
    }
    return ps::parseScene(text, path);
}

}  // namespace bench
