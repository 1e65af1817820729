// grade: the course's autograder (README, "The autograder"). Scores a submission lesson by
// lesson, each lesson IN ISOLATION: the lesson under test from the submission, every other
// lesson from the reference, prebuilt.
//
//   grade --prepare DIR [--source SRC] [--jobs N]
//   grade [--tree DIR] [--submission DIR] [--lessons 0,1|all] [--out OUT] [--timeout S]
//         [--build-timeout S] [--jobs N] [--no-sandbox] [--keep-work] [--expect zero|full] [--note TEXT]
//   grade --junit FILE [--source SRC] [--lessons ...] [--out OUT] [--expect zero|full]
//
// --prepare builds the reference once (in DIR/build) and assembles the prepared tree in DIR
// (cmake/grader.cmake: headers, the framework, every lesson's reference, plumbing and tests as
// objects, the data tests read, the build rules; no solution source). Every reference build makes
// one as a by-product in BUILD/grader, the default --tree.
// Grading compiles only the submission's files of each lesson, links them with the tree and runs
// each graded test alone, all in a sandbox with time limits (lesson.h, sandbox.h, process.h).
// With --junit nothing is built or run: the graded tests are scored from a CTest JUnit report
// (CI proves this way that the reference scores full marks and the skeleton zero).
// Writes OUT/results.json (Gradescope), OUT/junit.xml and OUT/logs/ (every step's output), and
// prints a score table. Exit status: 0; 1 when --expect is not met; 2 for a bad command line;
// 3 when there is no working sandbox and --no-sandbox was not given.
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "lesson.h"
#include "report.h"
#include "sandbox.h"

namespace fs = std::filesystem;
using namespace grade;

namespace {

// A bad command line: "grade: MESSAGE (see --help)", exit status 2.
[[noreturn]] void usageError(const std::string& message) {
    std::cerr << "grade: " << message << " (see --help)\n";
    std::exit(2);
}

// The whole of s as a whole number from lo to hi, else a usage error naming the option.
int wholeNumber(const std::string& option, const std::string& s, int lo, int hi) {
    long long v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size() || v < lo || v > hi)
        usageError(option + " needs a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) +
                   ", got '" + s + "'");
    return static_cast<int>(v);
}

std::string quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

const char* kHelp =
    "usage: grade --prepare DIR [--source SRC] [--jobs N]\n"
    "       grade [--tree DIR] [--submission DIR] [--lessons 0,1|all] [--out OUT] [--timeout S]\n"
    "             [--build-timeout S] [--jobs N] [--no-sandbox] [--keep-work] [--expect zero|full]\n"
    "             [--note TEXT]\n"
    "       grade --junit FILE [--source SRC] [--lessons 0,1|all] [--out OUT] [--expect zero|full]\n"
    "--prepare DIR builds the reference once and puts in DIR what grading needs (no solution source).\n"
    "Grading scores each lesson in isolation: that lesson from the submission (DIR holds lesson\n"
    "folders like assignments/, the default), every other lesson from the prepared tree (--tree,\n"
    "default: this build's grader/). Only the submission's files are compiled; the build and each\n"
    "test run in a sandbox (bubblewrap: no network, nothing but the submission's copy and the tree;\n"
    "as nobody when root). --no-sandbox runs them unprotected, as you (for trusted code only).\n"
    "--timeout S limits each graded test (default 120), --build-timeout S the build of a lesson\n"
    "(default 300): a test stopped scores 0 ('timed out after S s'), a build stopped scores 0 for\n"
    "the lesson. --jobs N compiles and runs N at a time (default 2). Writes OUT/results.json\n"
    "(Gradescope), OUT/junit.xml and OUT/logs/ (default OUT: ./grade). --keep-work keeps the\n"
    "work folders (their path is printed). --note TEXT goes first in results.json's output (what a\n"
    "wrapper such as the Gradescope package has to say about the upload).\n"
    "--junit FILE scores the graded tests from an existing CTest JUnit report instead of building.\n"
    "--expect zero|full: exit 1 unless every graded test failed / passed.\n"
    "Exit status 3: no working sandbox (install bubblewrap, or --no-sandbox).\n";

// grade --prepare: a reference build whose by-product is the tree.
int prepare(const fs::path& source, const fs::path& dir, int jobs) {
    const fs::path build = dir / "build";
    const std::string configure =
        "cmake -S " + quote(source.string()) + " -B " + quote(build.string()) +
        " -DCMAKE_BUILD_TYPE=Release -DPATHSPACE_STUDENT= -DPATHSPACE_GRADER_TREE=" + quote(dir.string());
    const std::string make =
        "cmake --build " + quote(build.string()) + " -j" + std::to_string(jobs) + " --target grader_tree";
    std::cerr << "grade: preparing " << dir.string() << " (reference build in " << build.string() << ")\n";
    if (std::system(configure.c_str()) != 0 || std::system(make.c_str()) != 0) {
        std::cerr << "grade: --prepare failed\n";
        return 1;
    }
    std::cerr << "grade: prepared " << dir.string() << "\n";
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const auto started = std::chrono::steady_clock::now();
    fs::path source = PATHSPACE_SOURCE_DIR, tree = PATHSPACE_GRADER_TREE;
    fs::path submission = source / "assignments", out = "grade", junitIn, prepareDir;
    std::string lessonsArg = "all", expect, note;
    int timeout = 120, buildTimeout = 300, jobs = 2;
    bool noSandbox = false, keepWork = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) usageError(a + " needs a value");
            return argv[++i];
        };
        if (a == "--submission") submission = fs::absolute(value());
        else if (a == "--lessons") lessonsArg = value();
        else if (a == "--out") out = value();
        else if (a == "--timeout") timeout = wholeNumber(a, value(), 1, 24 * 3600);
        else if (a == "--build-timeout") buildTimeout = wholeNumber(a, value(), 1, 24 * 3600);
        else if (a == "--jobs") jobs = wholeNumber(a, value(), 1, 256);
        else if (a == "--source") source = fs::absolute(value());
        else if (a == "--tree") tree = fs::absolute(value());
        else if (a == "--prepare") prepareDir = fs::absolute(value());
        else if (a == "--junit") junitIn = fs::absolute(value());
        else if (a == "--no-sandbox") noSandbox = true;
        else if (a == "--keep-work") keepWork = true;
        else if (a == "--note") note = value();
        else if (a == "--expect") {
            expect = value();
            if (expect != "zero" && expect != "full") usageError("--expect takes zero or full, got '" + expect + "'");
        } else if (a == "--help" || a == "-h") {
            std::cout << kHelp;
            return 0;
        } else usageError("unknown option " + a);
    }
    // --lessons: "all" or lesson numbers separated by commas ("0,1,7"); checked before anything runs.
    std::vector<int> wanted;
    if (lessonsArg != "all") {
        std::stringstream ss(lessonsArg);
        for (std::string k; std::getline(ss, k, ',');)
            if (!k.empty()) wanted.push_back(wholeNumber("--lessons", k, 0, 99));
        if (wanted.empty())
            usageError("--lessons needs 'all' or lesson numbers such as 0,1,7, got '" + lessonsArg + "'");
    }
    if (!prepareDir.empty()) return prepare(source, prepareDir, jobs);

    // The lessons: from the source's tests/ when scoring a report, else from the tree.
    const bool fromReport = !junitIn.empty();
    const fs::path listing = fromReport ? source / "tests" : tree / "tests";
    if (!fs::is_directory(listing)) {
        std::cerr << "grade: " << listing.string()
                  << (fromReport ? " not found" : " not found: no prepared tree there (grade --prepare DIR)") << "\n";
        return 2;
    }
    std::vector<std::string> lessons;
    for (const auto& e : fs::directory_iterator(listing)) {
        std::string n = e.path().filename().string();
        if (!fromReport && e.path().extension() == ".txt") n = e.path().stem().string();
        else if (fromReport != e.is_directory()) continue;
        if (n.size() > 3 && std::isdigit(static_cast<unsigned char>(n[0])) &&
            std::isdigit(static_cast<unsigned char>(n[1])) && n[2] == '-' &&
            (wanted.empty() || std::find(wanted.begin(), wanted.end(), std::stoi(n.substr(0, 2))) != wanted.end()))
            lessons.push_back(n);
    }
    std::sort(lessons.begin(), lessons.end());
    if (lessons.empty()) {
        std::cerr << "grade: no lesson matches '" << lessonsArg << "'\n";
        return 2;
    }
    if (fromReport && !fs::is_regular_file(junitIn)) {
        std::cerr << "grade: " << junitIn.string() << ": no such JUnit report\n";
        return 2;
    }

    out = fs::absolute(out);
    std::vector<TestResult> results;
    std::map<std::string, std::string> notes;
    notes[""] = note;
    if (fromReport) {  // score the report, nothing to build
        const std::map<std::string, TestResult> reported = readJUnit(junitIn);
        for (const std::string& lesson : lessons)
            for (const std::string& name : declaredTests(source / "tests" / lesson)) {
                auto it = reported.find(name);
                TestResult r = it != reported.end() ? it->second : TestResult();
                if (it == reported.end()) r.message = "not in " + junitIn.string();
                r.lesson = lesson;
                r.name = name;
                r.points = pointsOf(name);
                results.push_back(r);
            }
        fs::create_directories(out);
    } else {
        Grading g;
        g.tree = tree;
        g.submission = submission;
        g.testTimeout = timeout;
        g.buildTimeout = buildTimeout;
        g.jobs = jobs;
        if (!noSandbox) {
            std::string why;
            g.sandbox = Sandbox::probe(treeView(g, lessons.front()), why);
            if (!g.sandbox.on()) {
                std::cerr << "grade: no sandbox: " << why
                          << ".\ngrade: install it (apt-get install bubblewrap), or give --no-sandbox to run the "
                             "submission unprotected, as you (trusted code only)\n";
                return 3;
            }
            std::cerr << "grade: sandbox: bwrap" << (g.sandbox.unprivileged() ? ", as nobody" : "") << "\n";
        } else std::cerr << "grade: --no-sandbox: the submission runs as you and can read and change your files\n";
        fs::create_directories(out);
        g.logs = out / "logs";
        fs::remove_all(g.logs);
        fs::create_directories(g.logs);
        std::string work = (fs::temp_directory_path() / "pathspace-grade-XXXXXX").string();
        if (!mkdtemp(work.data())) {
            std::cerr << "grade: cannot make a work folder in " << fs::temp_directory_path().string() << "\n";
            return 1;
        }
        g.work = work;
        fs::permissions(g.work, fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec);
        for (const std::string& lesson : lessons) {
            std::cerr << "grade: lesson " << lesson << "\n";
            std::vector<TestResult> r = gradeLesson(g, lesson, notes[lesson]);
            results.insert(results.end(), r.begin(), r.end());
        }
        // Every step has ended, with every process it started (process.h): nothing but the grader
        // writes OUT from here on.
        if (keepWork) std::cerr << "grade: work folders kept in " << g.work.string() << "\n";
        else fs::remove_all(g.work);
    }
    // execution_time: the grading's wall time; for a report, the time its tests took.
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (fromReport) {
        seconds = 0;
        for (const TestResult& r : results) seconds += r.seconds;
    }
    writeReport(results, notes, out, !fromReport, seconds);
    std::cerr << "grade: wrote " << (out / "results.json").string()
              << (fromReport ? "" : " and " + (out / "junit.xml").string()) << "\n";
    if (!expect.empty()) {
        std::string wrong;
        for (const TestResult& r : results)
            if (r.passed != (expect == "full")) wrong += "  " + r.lesson + ": " + r.name + "\n";
        if (!wrong.empty()) {
            std::cerr << "grade: expected every graded test to " << (expect == "full" ? "pass" : "fail")
                      << "; these did not:\n"
                      << wrong;
            return 1;
        }
        std::cerr << "grade: all " << results.size() << " graded tests " << (expect == "full" ? "passed" : "failed")
                  << ", as expected\n";
    }
    return 0;
}
