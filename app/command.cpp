#include "command.h"
#include <algorithm>
#include <iostream>
#include "integrator.h"
#include "scene.h"
#if defined(_WIN32)
#include <io.h>
#else
#include <unistd.h>
#endif

namespace ps {

namespace {
std::vector<Command>& registry() {
    static std::vector<Command> commands;   // filled before main by static initialisers
    return commands;
}
}  // namespace

bool registerCommand(const Command& command) {
    registry().push_back(command);
    return true;
}

std::vector<Command> commandList() {
    std::vector<Command> list = registry();
    std::sort(list.begin(), list.end(), [](const Command& a, const Command& b) {
        return a.order != b.order ? a.order < b.order : a.name < b.name;
    });
    return list;
}

const Command* findCommand(const std::string& name) {
    for (const Command& c : registry())
        if (c.name == name) return &c;
    return nullptr;
}

std::string stem(const std::string& path) {
    size_t slash = path.find_last_of('/');
    size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return path;
    return path.substr(0, dot);
}

std::string baseName(const std::string& path) {
    size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::vector<std::string> splitList(const std::string& s) {
    std::vector<std::string> out;
    std::string cur;
    for (char c : s + ",") {
        if (c == ',') {
            if (!cur.empty()) out.push_back(cur);
            cur.clear();
        } else {
            cur += c;
        }
    }
    return out;
}

void printLeftOut(const std::string& algo, const Integrator& integrator, const Scene& scene) {
    for (const std::string& line : integrator.leftOut(scene))
        std::cerr << "pathspace: " << algo << " leaves out " << line << "\n";
}

void listAlgorithms(std::ostream& os) {
    const std::vector<IntegratorInfo> list = integratorList();
    size_t width = 0;
    for (const auto& i : list) width = std::max(width, i.name.size());
    os << "algorithms:\n";
    for (const auto& i : list) os << "  " << i.name << std::string(width + 2 - i.name.size(), ' ') << i.description << "\n";
}

bool stderrIsTerminal() {
#if defined(_WIN32)
    return _isatty(2) != 0;
#else
    return isatty(2) != 0;
#endif
}

}  // namespace ps
