// grade: scores a submission lesson by lesson, each lesson IN ISOLATION: the lesson under test
// is built from the submission, every other lesson from the reference (solutions/).
//
//   grade [--submission DIR] [--lessons 0,1|all] [--out DIR] [--timeout S] [--jobs N]
//   grade --junit FILE [--lessons ...] [--out DIR] [--expect zero|full]
//
// With --junit nothing is built: the graded tests are scored from a CTest JUnit report that
// already exists (`ctest --output-junit FILE`). CI uses it to prove that the reference scores
// full marks and the untouched skeleton scores 0 (--expect: exit 1, naming the tests, if not).
//
// DIR holds lesson folders like assignments/ does (NN-name/*.cpp); default: assignments/. A
// submission holds only the student's pieces: each lesson's plumbing (integrator registration,
// task loops) is compiled from lessons/NN-name/*.cpp, and a submitted file with the name of one
// of those is left out (cmake/lessons.cmake), so a student cannot change how a lesson is run.
// For each lesson: configure and build in OUT/build-NN, run its graded tests (CTest label
// lesson-NN) with a per-test timeout (given to CMake as PATHSPACE_TEST_TIMEOUT, since the tests'
// TIMEOUT property would win over ctest --timeout), read CTest's JUnit report and, for the tests
// stopped by the timeout, ctest's log (the JUnit report does not say). A test's points are in its
// name ("... [3 pts]", else 1). A lesson that does not build scores 0 on every test; a test
// that crashes or times out scores 0; the other tests are still graded.
// Writes OUT/results.json (Gradescope format), OUT/junit.xml, and prints a score table.
#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct TestResult {
    std::string lesson, name, message, output;
    int points = 1;
    bool passed = false;
    bool timedOut = false;  // stopped by the per-test timeout (then message says after how long)
};

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

std::string readText(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::string quote(const std::string& s) { return "'" + s + "'"; }

int run(const std::string& cmd) {
    const int rc = std::system(cmd.c_str());
    return rc == 0 ? 0 : 1;
}

int pointsOf(const std::string& name) {
    static const std::regex re(R"(\[(\d+) pts?\])");
    std::smatch m;
    return std::regex_search(name, m, re) ? std::stoi(m[1]) : 1;
}

std::string xmlUnescape(std::string s) {
    const std::pair<const char*, const char*> ents[] = {{"&quot;", "\""}, {"&apos;", "'"}, {"&lt;", "<"}, {"&gt;", ">"},
                                                        {"&#10;", "\n"},  {"&#13;", "\r"}, {"&amp;", "&"}};
    for (auto [from, to] : ents)
        for (size_t p = 0; (p = s.find(from, p)) != std::string::npos; p += std::string(to).size())
            s.replace(p, std::string(from).size(), to);
    return s;
}

std::string xmlEscape(const std::string& s) {
    std::string out;
    for (char c : s) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default:
            if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') out += ' ';
            else out += c;
        }
    }
    return out;
}

std::string jsonEscape(const std::string& s) {
    std::string out;
    for (unsigned char c : s) {
        switch (c) {
        case '"': out += "\\\""; break;
        case '\\': out += "\\\\"; break;
        case '\n': out += "\\n"; break;
        case '\t': out += "\\t"; break;
        default:
            if (c < 0x20) {
                char b[8];
                std::snprintf(b, sizeof b, "\\u%04x", c);
                out += b;
            } else out += static_cast<char>(c);
        }
    }
    return out;
}

std::string lastLines(const std::string& text, int n) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    std::string out;
    for (size_t i = lines.size() > size_t(n) ? lines.size() - n : 0; i < lines.size(); ++i) out += lines[i] + "\n";
    return out;
}

// The graded tests a lesson declares: TEST_CASE("name" ...) in tests/NN-name/*.cpp.
std::vector<std::string> declaredTests(const fs::path& dir) {
    static const std::regex re(R"re(TEST_CASE\s*\(\s*"((?:[^"\\]|\\.)*)")re");
    std::vector<std::string> names;
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().extension() == ".cpp") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& f : files) {
        const std::string text = readText(f);
        for (std::sregex_iterator it(text.begin(), text.end(), re), end; it != end; ++it) names.push_back((*it)[1]);
    }
    return names;
}

// The value of attribute `name` in the start tag `tag` ("" if absent).
std::string attribute(const std::string& tag, const std::string& name) {
    const std::string key = " " + name + "=\"";
    const size_t a = tag.find(key);
    if (a == std::string::npos) return "";
    const size_t b = a + key.size(), e = tag.find('"', b);
    return e == std::string::npos ? "" : tag.substr(b, e - b);
}

// name -> (passed, failure message, output) from a CTest JUnit file. Parsed with find(), not
// std::regex: libstdc++'s regex recurses per character and overflows the stack on the
// megabytes of output a failing skeleton produces.
std::map<std::string, TestResult> readJUnit(const fs::path& file) {
    std::map<std::string, TestResult> out;
    const std::string xml = readText(file);
    for (size_t pos = 0; (pos = xml.find("<testcase", pos)) != std::string::npos;) {
        const size_t tagEnd = xml.find('>', pos);
        if (tagEnd == std::string::npos) break;
        const std::string tag = xml.substr(pos, tagEnd - pos);
        std::string body;
        size_t next = tagEnd + 1;
        if (xml[tagEnd - 1] != '/') {  // <testcase ...> body </testcase>
            const size_t close = xml.find("</testcase>", tagEnd);
            body = xml.substr(tagEnd + 1, (close == std::string::npos ? xml.size() : close) - tagEnd - 1);
            next = close == std::string::npos ? xml.size() : close;
        }
        pos = next;
        TestResult r;
        r.name = xmlUnescape(attribute(tag, "name"));
        const std::string status = attribute(tag, "status");
        const size_t failure = body.find("<failure");
        r.passed = status == "run" && failure == std::string::npos;
        if (failure != std::string::npos)
            r.message = xmlUnescape(attribute(body.substr(failure, body.find('>', failure) - failure), "message"));
        const size_t so = body.find("<system-out>");
        if (so != std::string::npos) {
            const size_t b = so + std::string("<system-out>").size(), e = body.find("</system-out>", b);
            r.output = xmlUnescape(body.substr(b, (e == std::string::npos ? body.size() : e) - b));
        }
        if (!r.passed && r.message.empty()) r.message = status == "notrun" ? "not run" : "failed";
        out[r.name] = r;
    }
    return out;
}

// The tests ctest stopped at their timeout, from its log: it ends with
//   The following tests FAILED:
//   	  3 - NAME (Timeout)
// (CTest's JUnit report says only "fail" for them, with an empty message.)
std::set<std::string> timedOutTests(const fs::path& ctestLog) {
    std::set<std::string> names;
    std::istringstream in(readText(ctestLog));
    const std::string tail = " (Timeout)";
    for (std::string l; std::getline(in, l);) {
        if (!l.empty() && l.back() == '\r') l.pop_back();
        if (l.size() <= tail.size() || l.compare(l.size() - tail.size(), tail.size(), tail) != 0) continue;
        const size_t start = l.find_first_not_of(" \t"), dash = l.find(" - ");
        if (start == std::string::npos || dash == std::string::npos ||
            !std::isdigit(static_cast<unsigned char>(l[start])))
            continue;
        names.insert(l.substr(dash + 3, l.size() - tail.size() - dash - 3));
    }
    return names;
}

// The first lines of a failed doctest run that say what went wrong.
std::string failureSummary(const TestResult& r) {
    std::istringstream in(r.output);
    std::string summary;
    int kept = 0;
    for (std::string l; std::getline(in, l) && kept < 12;) {
        if (l.find("ERROR") != std::string::npos || l.find("CHECK") != std::string::npos ||
            l.find("REQUIRE") != std::string::npos || l.find("values:") != std::string::npos ||
            l.find("logged:") != std::string::npos || l.find("with expansion") != std::string::npos ||
            l.find("  ") == 0) {
            summary += l + "\n";
            ++kept;
        }
    }
    if (r.timedOut) return r.message + (summary.empty() ? "" : "\n" + summary);
    return summary.empty() ? r.message : summary;
}

}  // namespace

int main(int argc, char** argv) {
    fs::path source = PATHSPACE_SOURCE_DIR;
    fs::path submission = source / "assignments";
    fs::path out = "grade";
    std::string lessonsArg = "all", expect;
    fs::path junitIn;
    int timeout = 120, jobs = 2;
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
        else if (a == "--jobs") jobs = wholeNumber(a, value(), 1, 256);
        else if (a == "--source") source = fs::absolute(value());
        else if (a == "--junit") junitIn = fs::absolute(value());
        else if (a == "--expect") {
            expect = value();
            if (expect != "zero" && expect != "full") {
                std::cerr << "grade: --expect takes zero or full\n";
                return 2;
            }
        } else if (a == "--help" || a == "-h") {
            std::cout
                << "usage: grade [--submission DIR] [--lessons 0,1|all] [--out DIR] [--timeout SECONDS] [--jobs N]\n"
                   "       grade --junit FILE [--lessons 0,1|all] [--out DIR] [--expect zero|full]\n"
                   "Scores each lesson in isolation (that lesson from DIR, the others from solutions/).\n"
                   "DIR holds lesson folders like assignments/ (default: assignments/). Writes\n"
                   "OUT/results.json (Gradescope) and OUT/junit.xml (default OUT: ./grade).\n"
                   "--timeout SECONDS limits each graded test (default 120; a test it stops scores 0 and is\n"
                   "reported as 'timed out after SECONDS s'); --jobs N builds and tests N at a time (default 2).\n"
                   "--junit FILE scores the graded tests from an existing CTest JUnit report instead of\n"
                   "building; --expect zero|full then exits 1 unless every graded test failed / passed.\n";
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
    out = fs::absolute(out);
    fs::create_directories(out);
    if (!fs::is_directory(source / "solutions")) {
        std::cerr << "grade: " << (source / "solutions").string() << " not found: grading needs the reference\n";
        return 2;
    }

    // Lessons with graded tests.
    std::vector<std::string> lessons;
    for (const auto& e : fs::directory_iterator(source / "tests")) {
        const std::string n = e.path().filename().string();
        if (e.is_directory() && n.size() > 3 && std::isdigit(n[0]) && std::isdigit(n[1]) && n[2] == '-') {
            if (lessonsArg == "all") {
                lessons.push_back(n);
                continue;
            }
            if (std::find(wanted.begin(), wanted.end(), std::stoi(n.substr(0, 2))) != wanted.end())
                lessons.push_back(n);
        }
    }
    std::sort(lessons.begin(), lessons.end());
    if (lessons.empty()) {
        std::cerr << "grade: no lesson matches '" << lessonsArg << "'\n";
        return 2;
    }

    std::vector<TestResult> results;
    std::string junit = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites>\n";
    if (!junitIn.empty() && !fs::is_regular_file(junitIn)) {
        std::cerr << "grade: " << junitIn.string() << ": no such JUnit report\n";
        return 2;
    }
    const std::map<std::string, TestResult> reported =
        junitIn.empty() ? std::map<std::string, TestResult>() : readJUnit(junitIn);
    for (const std::string& lesson : lessons) {
        const std::string nn = lesson.substr(0, 2);
        if (!junitIn.empty()) {  // score from the report, nothing to build
            for (const std::string& name : declaredTests(source / "tests" / lesson)) {
                auto it = reported.find(name);
                TestResult r = it != reported.end() ? it->second : TestResult();
                if (it == reported.end()) r.message = "not in " + junitIn.string();
                r.lesson = lesson;
                r.name = name;
                r.points = pointsOf(name);
                results.push_back(r);
            }
            continue;
        }
        const fs::path build = out / ("build-" + nn), log = out / ("build-" + nn + ".log");
        std::cerr << "grade: lesson " << lesson << ": building (log: " << log.string() << ")\n";
        // The tests' own TIMEOUT property (tests/CMakeLists.txt) wins over ctest --timeout, so the
        // grader's timeout is given to both: the cache variable sets the property.
        const bool built =
            run("cmake -S " + quote(source.string()) + " -B " + quote(build.string()) +
                " -DCMAKE_BUILD_TYPE=Release -DPATHSPACE_TEST_TIMEOUT=" + std::to_string(timeout) +
                " -DPATHSPACE_STUDENT=" + nn + " -DPATHSPACE_ASSIGNMENTS_DIR=" + quote(submission.string()) + " > " +
                quote(log.string()) + " 2>&1") == 0 &&
            run("cmake --build " + quote(build.string()) + " -j" + std::to_string(jobs) + " --target lesson_" + nn +
                "_tests >> " + quote(log.string()) + " 2>&1") == 0;
        std::map<std::string, TestResult> ran;
        if (built) {
            const fs::path xml = out / ("junit-" + nn + ".xml"), ctestLog = out / ("ctest-" + nn + ".log");
            fs::remove(xml);
            run("ctest --test-dir " + quote(build.string()) + " -L lesson-" + nn + " --timeout " +
                std::to_string(timeout) + " -j" + std::to_string(jobs) + " --output-junit " + quote(xml.string()) +
                " > " + quote(ctestLog.string()) + " 2>&1");
            ran = readJUnit(xml);
            for (const std::string& name : timedOutTests(ctestLog)) {
                auto it = ran.find(name);
                if (it == ran.end() || it->second.passed) continue;
                it->second.timedOut = true;
                it->second.message = "timed out after " + std::to_string(timeout) + " s";
            }
            std::string suite = readText(xml);
            if (size_t p = suite.find("?>"); p != std::string::npos) suite = suite.substr(p + 2);
            junit += suite + "\n";
        }
        const std::string buildError =
            built ? "" : "the lesson did not build; the end of " + log.string() + ":\n" + lastLines(readText(log), 25);
        for (const std::string& name : declaredTests(source / "tests" / lesson)) {
            TestResult r;
            auto it = ran.find(name);
            if (it != ran.end()) r = it->second;
            else r.message = built ? "not run (did the test executable crash at start-up?)" : buildError;
            r.lesson = lesson;
            r.name = name;
            r.points = pointsOf(name);
            results.push_back(r);
        }
        if (!built)
            junit += "<testsuite name=\"lesson-" + nn + "\"><testcase name=\"build\"><failure message=\"" +
                     xmlEscape(buildError) + "\"/></testcase></testsuite>\n";
    }
    junit += "</testsuites>\n";
    if (junitIn.empty()) std::ofstream(out / "junit.xml") << junit;

    // Score table and Gradescope results.
    int score = 0, maxScore = 0;
    std::map<std::string, std::pair<int, int>> perLesson;
    std::ostringstream tests;
    std::printf("\n%-16s %-70s %6s  %s\n", "lesson", "test", "points", "result");
    for (size_t i = 0; i < results.size(); ++i) {
        const TestResult& r = results[i];
        const int got = r.passed ? r.points : 0;
        score += got;
        maxScore += r.points;
        perLesson[r.lesson].first += got;
        perLesson[r.lesson].second += r.points;
        std::printf("%-16s %-70.70s %3d/%-2d  %s\n", r.lesson.c_str(), r.name.c_str(), got, r.points,
                    r.passed     ? "pass"
                    : r.timedOut ? "TIMEOUT"
                                 : "FAIL");
        const std::string why = r.passed ? "" : failureSummary(r);
        if (!r.passed) {
            std::istringstream in(why);
            for (std::string l; std::getline(in, l);) std::printf("%16s     %s\n", "", l.c_str());
        }
        tests << (i ? ",\n" : "") << "    {\"name\": \"" << jsonEscape(r.lesson + ": " + r.name)
              << "\", \"score\": " << got << ", \"max_score\": " << r.points << ", \"status\": \""
              << (r.passed ? "passed" : "failed") << "\", \"output\": \"" << jsonEscape(why) << "\"}";
    }
    std::printf("\n");
    for (const auto& [lesson, s] : perLesson) std::printf("%-16s %d / %d\n", lesson.c_str(), s.first, s.second);
    std::printf("%-16s %d / %d\n", "total", score, maxScore);
    std::ofstream(out / "results.json") << "{\n  \"score\": " << score << ",\n  \"max_score\": " << maxScore
                                        << ",\n  \"tests\": [\n"
                                        << tests.str() << "\n  ]\n}\n";
    std::cerr << "grade: wrote " << (out / "results.json").string()
              << (junitIn.empty() ? " and " + (out / "junit.xml").string() : "") << "\n";
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
