// skeleton: one source for solutions and assignments.
//
// A solution file marks each piece the student writes:
//
//     //! TODO(01) Warp u to a cosine-weighted direction (Eq. 1.12).   <- kept as "// TODO(01) ..."
//     //!          continuation of the TODO text                         <- kept as a comment
//     //! STUB return PS_TODO("sampleCosineHemisphere", Vec3(0, 0, 1));  <- becomes code
//     //! BEGIN
//     ... the solution ...                                               <- removed
//     //! END
//
// A solution .cpp file without any marker is refused: with nothing for the student to write it
// is the lesson's plumbing, which lives in lessons/NN-name/ (cmake/lessons.cmake).
//
// usage:
//   skeleton generate SOLUTIONS ASSIGNMENTS   write every assignment file from its solution
//   skeleton check    SOLUTIONS ASSIGNMENTS   exit 1 if any assignment file is out of sync
//   skeleton leaks    SOLUTIONS TREE          exit 1 if solution code occurs in TREE
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct Failure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

std::vector<std::string> readLines(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    if (!in) throw Failure(p.string() + ": cannot open");
    std::vector<std::string> lines;
    for (std::string s; std::getline(in, s);) lines.push_back(s);
    return lines;
}

std::string readText(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// The marker of a line ("BEGIN", "END", "STUB", "TEXT") and what follows it; "" if none.
std::string marker(const std::string& line, std::string& indent, std::string& rest) {
    const size_t i = line.find_first_not_of(" \t");
    if (i == std::string::npos || line.compare(i, 3, "//!") != 0) return "";
    indent = line.substr(0, i);
    std::string body = line.substr(i + 3);
    const size_t j = body.find_first_not_of(' ');
    body = j == std::string::npos ? "" : body.substr(j);
    for (const char* kw : {"BEGIN", "END", "STUB"}) {
        const size_t n = std::string(kw).size();
        if (body.compare(0, n, kw) == 0 && (body.size() == n || body[n] == ' ')) {
            rest = body.size() > n ? body.substr(n + 1) : "";
            return kw;
        }
    }
    rest = line.substr(i + 3);  // keep the text's own spacing after "//!"
    return "TEXT";
}

// The assignment text of one solution file, and (out) the lines of its solution regions.
std::string makeAssignment(const fs::path& file, std::vector<std::string>* regionLines,
                           std::vector<std::vector<std::string>>* regions = nullptr) {
    std::ostringstream out;
    bool inRegion = false;
    int regionStart = 0, lineNo = 0;
    for (const std::string& line : readLines(file)) {
        ++lineNo;
        std::string indent, rest;
        const std::string m = marker(line, indent, rest);
        const std::string where = file.string() + ":" + std::to_string(lineNo) + ": ";
        if (m == "BEGIN") {
            if (inRegion)
                throw Failure(where + "//! BEGIN inside the region opened at line " + std::to_string(regionStart));
            inRegion = true;
            regionStart = lineNo;
            if (regions) regions->emplace_back();
        } else if (m == "END") {
            if (!inRegion) throw Failure(where + "//! END without //! BEGIN");
            inRegion = false;
        } else if (inRegion) {
            if (!m.empty()) throw Failure(where + "//! marker inside a solution region");
            if (regionLines) regionLines->push_back(line);
            if (regions) regions->back().push_back(line);
        } else if (m == "STUB") {
            out << indent << rest << "\n";
        } else if (m == "TEXT") {
            out << indent << "//" << rest << "\n";
        } else {
            out << line << "\n";
        }
    }
    if (inRegion) throw Failure(file.string() + ":" + std::to_string(regionStart) + ": //! BEGIN without //! END");
    return out.str();
}

// Every file below dir, as paths relative to it, sorted.
std::vector<fs::path> filesBelow(const fs::path& dir) {
    std::vector<fs::path> files;
    if (!fs::is_directory(dir)) throw Failure(dir.string() + ": not a directory");
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file()) files.push_back(fs::relative(e.path(), dir));
    std::sort(files.begin(), files.end());
    return files;
}

int generate(const fs::path& sol, const fs::path& asg, bool checkOnly) {
    int stale = 0;
    std::set<fs::path> expected;
    for (const fs::path& rel : filesBelow(sol)) {
        expected.insert(rel);
        const std::string text = makeAssignment(sol / rel, nullptr);
        // A file with nothing for the student to write is the lesson's plumbing: it is compiled
        // from lessons/NN-name/ (cmake/lessons.cmake), so the student's folder holds only pieces.
        if (rel.extension() == ".cpp" && text == readText(sol / rel))
            throw Failure((sol / rel).string() +
                          ": no //! marker, nothing for the student to write: plumbing belongs in "
                          "lessons/" +
                          rel.parent_path().string() + "/ (cmake/lessons.cmake compiles it from there)");
        const fs::path target = asg / rel;
        if (fs::exists(target) && readText(target) == text) continue;
        if (checkOnly) {
            std::cerr << "skeleton: " << target.string() << " is out of sync with " << (sol / rel).string() << "\n";
            ++stale;
        } else {
            fs::create_directories(target.parent_path());
            std::ofstream(target, std::ios::binary) << text;
            std::cout << "skeleton: wrote " << target.string() << "\n";
        }
    }
    if (fs::is_directory(asg))
        for (const fs::path& rel : filesBelow(asg))
            if (!expected.count(rel)) {
                if (checkOnly) {
                    std::cerr << "skeleton: " << (asg / rel).string() << " has no solution file "
                              << (sol / rel).string() << "\n";
                    ++stale;
                } else {
                    fs::remove(asg / rel);
                    std::cout << "skeleton: removed " << (asg / rel).string() << "\n";
                }
            }
    if (stale)
        std::cerr << "skeleton: " << stale << " file(s) out of sync; run: cmake --build build --target assignments\n";
    return stale ? 1 : 0;
}

// Whitespace-collapsed form of a line, for comparing code.
std::string normalise(const std::string& s) {
    std::string out;
    bool space = false;
    for (char c : s) {
        if (c == ' ' || c == '\t' || c == '\r') {
            space = !out.empty();
            continue;
        }
        if (space) out += ' ';
        space = false;
        out += c;
    }
    return out;
}

// The code lines of a text: whitespace-collapsed, without blank lines and comment lines.
std::vector<std::pair<std::string, int>> codeLines(const std::vector<std::string>& lines) {
    std::vector<std::pair<std::string, int>> out;
    for (size_t i = 0; i < lines.size(); ++i) {
        const std::string n = normalise(lines[i]);
        if (!n.empty() && n.compare(0, 2, "//") != 0 && n != "{" && n != "}" && n != "};")
            out.emplace_back(n, int(i) + 1);
    }
    return out;
}

// A leak is a solution region's code showing up in the handout: any 3 consecutive code lines
// of a region, or a whole region of 1-2 lines if it is long enough to be distinctive. (Single
// short lines like "for (int i = 0; i < n; ++i) {" occur everywhere and prove nothing.)
int leaks(const fs::path& sol, const fs::path& tree) {
    constexpr size_t kWindow = 3, kMinShortRegion = 40;
    std::map<std::string, std::string> secret;  // lines joined by '\n' -> where they come from
    std::set<size_t> sizes;
    for (const fs::path& rel : filesBelow(sol)) {
        std::vector<std::vector<std::string>> regions;
        std::vector<std::string> all;
        makeAssignment(sol / rel, &all, &regions);
        for (const auto& region : regions) {
            std::vector<std::string> code;
            for (const auto& [line, no] : codeLines(region)) code.push_back(line);
            auto add = [&](size_t from, size_t n) {
                std::string key;
                for (size_t k = 0; k < n; ++k) key += code[from + k] + "\n";
                if (n < kWindow && key.size() < kMinShortRegion) return;
                secret.emplace(key, (sol / rel).string());
                sizes.insert(n);
            };
            if (code.size() >= kWindow)
                for (size_t i = 0; i + kWindow <= code.size(); ++i) add(i, kWindow);
            else if (!code.empty()) add(0, code.size());
        }
    }
    int found = 0;
    for (const fs::path& rel : filesBelow(tree)) {
        const auto code = codeLines(readLines(tree / rel));
        for (size_t n : sizes)
            for (size_t i = 0; i + n <= code.size(); ++i) {
                std::string key;
                for (size_t k = 0; k < n; ++k) key += code[i + k].first + "\n";
                auto it = secret.find(key);
                if (it == secret.end()) continue;
                std::cerr << "skeleton: " << (tree / rel).string() << ":" << code[i].second << " holds " << n
                          << " line(s) of a solution region of " << it->second << ":\n"
                          << key;
                ++found;
            }
    }
    std::cout << "skeleton: " << secret.size() << " pieces of solution code checked against " << tree.string() << ": "
              << (found ? std::to_string(found) + " found" : std::string("none found")) << "\n";
    return found ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
    const std::string usage = "usage: skeleton generate|check|leaks SOLUTIONS DIR\n";
    if (argc != 4) {
        std::cerr << usage;
        return 2;
    }
    const std::string cmd = argv[1];
    try {
        if (cmd == "generate") return generate(argv[2], argv[3], false);
        if (cmd == "check") return generate(argv[2], argv[3], true);
        if (cmd == "leaks") return leaks(argv[2], argv[3]);
    } catch (const std::exception& e) {
        std::cerr << "skeleton: " << e.what() << "\n";
        return 1;
    }
    std::cerr << usage;
    return 2;
}
