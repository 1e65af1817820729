// score: the student's score, without the reference: the graded tests of each lesson as the
// student's own build ran them (a CTest JUnit report), in the grader's table (tools/grade/report.h)
// with the same points. scripts/score.sh builds, runs the tests and calls it.
//
//   score --source SRC --junit FILE [--lessons 0,3|all] [--out DIR]
//
// Every graded test the lesson declares (tests/NN-name/*.cpp) is listed: one the report does not
// have (its lesson did not build, or it was not run) scores 0. Writes DIR/results.json (default
// DIR: ./score). Exit status 0, 1 when results.json cannot be written, 2 for a bad command line.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "grade/report.h"

namespace fs = std::filesystem;
using namespace grade;

namespace {

[[noreturn]] void usage(const std::string& message) {
    std::cerr << "score: " << message << "\nusage: score --source SRC --junit FILE [--lessons 0,3|all] [--out DIR]\n";
    std::exit(2);
}

// "all" or "0,3,7" -> the lesson numbers (empty: all).
std::set<int> parseLessons(const std::string& s) {
    std::set<int> wanted;
    if (s == "all") return wanted;
    std::stringstream in(s);
    for (std::string item; std::getline(in, item, ',');) {
        if (item.empty() || item.size() > 2 || item.find_first_not_of("0123456789") != std::string::npos)
            usage("--lessons needs 'all' or lesson numbers such as 0,3, got '" + s + "'");
        wanted.insert(std::stoi(item));
    }
    return wanted;
}

// One line for the table that says why a test failed: the pieces the test ran into that are still
// TODO, then the test's own message (the first failure's "ERROR:" line, which the test programs'
// reporter makes the test's message, tests/support/doctest_main.cpp; or doctest's first "logged:"
// line: what it expected and what it
// got; its next line too when the first ends in "got"), at most about two lines of a terminal.
// The test's whole output stays in results.json.
std::string whyFailed(const TestResult& r) {
    const std::string& out = r.output;
    auto line = [&](size_t from) { return out.substr(from, out.find('\n', from) - from); };
    auto trim = [](std::string t) {
        const size_t a = t.find_first_not_of(" \t"), b = t.find_last_not_of(" \t\r");
        return a == std::string::npos ? std::string() : t.substr(a, b - a + 1);
    };
    std::string todo;
    const std::string marker = "TODO not done yet: ";
    for (size_t p = out.find(marker); p != std::string::npos; p = out.find(marker, p)) {
        p += marker.size();
        const std::string piece = trim(out.substr(p, out.find_first_of("(\n", p) - p));
        if (!piece.empty() && todo.find(piece) == std::string::npos) todo += (todo.empty() ? "" : ", ") + piece;
    }
    std::string logged;
    size_t l = out.find("ERROR: "), skip = 7;
    if (l == std::string::npos || out.compare(l + 7, 7, "CHECK( ") == 0 || out.compare(l + 7, 9, "REQUIRE( ") == 0) {
        l = out.find("logged: ");  // a check without a message, or doctest's own reporter
        skip = 8;
    }
    if (l != std::string::npos) {
        logged = trim(line(l + skip));
        const size_t next = out.find('\n', l);
        if (logged.size() >= 3 && logged.compare(logged.size() - 3, 3, "got") == 0 && next != std::string::npos)
            logged += " " + trim(line(next + 1));
    }
    std::string why = todo.empty() ? "" : marker + todo;
    if (!logged.empty()) why += (why.empty() ? "" : "; ") + logged;
    if (why.empty()) return r.message;
    constexpr size_t kMax = 220;
    return why.size() > kMax ? why.substr(0, kMax - 3) + "..." : why;
}

}  // namespace

int main(int argc, char** argv) {
    fs::path source, junit, out = "score";
    std::string lessonsArg = "all";
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) usage(a + " needs a value");
            return argv[++i];
        };
        if (a == "--source") source = value();
        else if (a == "--junit") junit = value();
        else if (a == "--lessons") lessonsArg = value();
        else if (a == "--out") out = value();
        else usage("unknown argument '" + a + "'");
    }
    if (source.empty() || junit.empty()) usage("--source and --junit are needed");
    const std::set<int> wanted = parseLessons(lessonsArg);
    if (!fs::is_directory(source / "tests")) usage(source.string() + "/tests: no such folder");

    std::vector<std::string> lessons;
    for (const auto& e : fs::directory_iterator(source / "tests")) {
        const std::string n = e.path().filename().string();
        if (e.is_directory() && n.size() > 3 && std::isdigit(static_cast<unsigned char>(n[0])) &&
            std::isdigit(static_cast<unsigned char>(n[1])) && n[2] == '-' &&
            (wanted.empty() || wanted.count(std::stoi(n.substr(0, 2)))))
            lessons.push_back(n);
    }
    std::sort(lessons.begin(), lessons.end());
    if (lessons.empty()) usage("no lesson matches '" + lessonsArg + "'");

    const std::map<std::string, TestResult> reported =
        fs::is_regular_file(junit) ? readJUnit(junit) : std::map<std::string, TestResult>();
    std::vector<TestResult> results;
    std::map<std::string, std::string> notes;
    for (const std::string& lesson : lessons) {
        int missing = 0;
        for (const std::string& name : declaredTests(source / "tests" / lesson)) {
            auto it = reported.find(name);
            TestResult r = it != reported.end() ? it->second : TestResult();
            if (it == reported.end()) {
                r.message = "not run (did the lesson build?)";
                ++missing;
            }
            r.lesson = lesson;
            r.name = name;
            r.points = pointsOf(name);
            if (!r.passed) r.message = whyFailed(r);
            results.push_back(r);
        }
        if (missing) notes[lesson] = std::to_string(missing) + " graded test(s) did not run";
    }
    std::error_code ec;
    fs::create_directories(out, ec);
    if (!fs::is_directory(out)) usage("--out " + out.string() + ": cannot make that folder");
    double seconds = 0;  // execution_time: the time the tests took in the student's run
    for (const TestResult& r : results) seconds += r.seconds;
    try {
        writeReport(results, notes, out, false, seconds);
    } catch (const std::exception& e) {
        std::cerr << "score: " << e.what() << "\n";
        return 1;
    }
    std::cout << "\nA test's whole message:\n  ctest --test-dir build -L lesson-NN -R 'part of its name' "
                 "--output-on-failure\n";
    return 0;
}
