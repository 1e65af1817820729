// What several benchmarks need: a scene at a chosen resolution, the process's CPU time, the
// machine's load average, a median.
#pragma once
#include <time.h>
#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>
#include "scene_loader.h"

namespace bench {

// A scene file loaded with its camera's resolution set to res x res (res > 0; otherwise as the
// file says), so that a benchmark can render any scene small and fast.
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

// The CPU time of the whole process (all threads): on a machine that other jobs keep busy,
// wall-clock time also counts the time slices the system gave to them.
inline double processCpuSeconds() {
    timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// "1.02 1.35 1.41" (1, 5 and 15 minutes), or "unknown" without /proc/loadavg.
inline std::string loadAverage() {
    std::ifstream in("/proc/loadavg");
    std::string a, b, c;
    in >> a >> b >> c;
    return a.empty() ? "unknown" : a + " " + b + " " + c;
}

inline double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

}  // namespace bench
