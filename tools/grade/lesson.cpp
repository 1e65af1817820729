// Grading one lesson from the prepared tree (lesson.h).
#include "lesson.h"

#include <unistd.h>

#include <fstream>
#include <regex>
#include <sstream>

namespace fs = std::filesystem;

namespace grade {

namespace {

// A file name the build rules can take as it is: no spaces, quotes, '$' or leading dash.
bool plainName(const std::string& n) {
    static const std::regex re("[A-Za-z0-9_][A-Za-z0-9_.+-]*");
    return std::regex_match(n, re);
}

std::vector<std::string> lines(const fs::path& file) {
    std::vector<std::string> out;
    std::ifstream in(file);
    for (std::string l; std::getline(in, l);)
        if (!l.empty()) out.push_back(l);
    return out;
}

// doctest's --test-case takes filters separated by commas: a comma in a name is escaped.
std::string doctestFilter(const std::string& name) {
    std::string f;
    for (char c : name) f += c == ',' ? std::string("\\,") : std::string(1, c);
    return f;
}

// A folder submission code may write to: owned by nobody when it runs as nobody.
void makeWritable(const fs::path& dir, const Sandbox& box) {
    fs::create_directories(dir);
    fs::permissions(dir, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec | fs::perms::others_read |
                             fs::perms::others_exec);
    if (box.unprivileged() && chown(dir.c_str(), kNobody, kNobody) != 0)
        throw std::runtime_error("cannot give " + dir.string() + " to uid " + std::to_string(kNobody));
}

const fs::perms kReadable =
    fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read | fs::perms::others_read;

// The end of a long text (a build log), whole lines.
std::string tail(const std::string& text, int n) {
    size_t p = text.size();
    for (int i = 0; i <= n && p != std::string::npos && p > 0; ++i) p = text.rfind('\n', p - 1);
    return p == std::string::npos || p == 0 ? text : text.substr(p + 1);
}

// What a test printed, for its report: all of it up to 64 KiB, else the start and the end
// (doctest's summary is at the end).
std::string clip(const std::string& s) {
    const size_t max = 64 << 10;
    if (s.size() <= max) return s;
    return s.substr(0, max / 4) + "\n[... " + std::to_string(s.size() - max) + " bytes left out ...]\n" +
           s.substr(s.size() - 3 * max / 4);
}

// The environment of every step: nothing of the grader's.
std::vector<std::string> environment(const fs::path& home) {
    return {"PATH=/usr/bin:/bin", "HOME=" + home.string(), "TMPDIR=" + home.string(), "LC_ALL=C", "MAKEFLAGS="};
}

// The verdict on one test from its outcome and what it printed.
void judge(TestResult& r, const Outcome& o, const std::string& output, double timeout, bool sandboxed) {
    r.seconds = o.seconds;
    r.output = clip(output);
    if (o.timedOut) {
        r.timedOut = true;
        r.message = o.describe(timeout);
        return;
    }
    if (!o.error.empty()) {
        r.message = o.error;
        return;
    }
    // bwrap reports a command killed by signal N as exit status 128 + N.
    if (o.signal || (sandboxed && o.exitCode > 128 && o.exitCode < 128 + 65)) {
        Outcome killed = o;
        killed.signal = o.signal ? o.signal : o.exitCode - 128;
        r.message = "crashed: " + killed.describe(timeout);
        return;
    }
    static const std::regex summary(R"(\[doctest\] test cases:\s*(\d+)\s*\|\s*(\d+) passed\s*\|\s*(\d+) failed)");
    std::smatch m;
    std::string last;  // the last summary line: the one doctest prints as the program ends
    for (std::sregex_iterator it(output.begin(), output.end(), summary), end; it != end; ++it) last = it->str();
    const bool counted = std::regex_search(last, m, summary);
    if (o.exitCode == 0 && counted && m[1] == "1" && m[2] == "1" && m[3] == "0") {
        r.passed = true;
        return;
    }
    if (o.exitCode == 0) {
        r.message = counted ? "the test's name selected " + m[1].str() + " test cases, not 1"
                            : "the test program exited 0 without doctest's summary (did the submission end it?)";
        return;
    }
    const size_t error = output.find("ERROR:");
    r.message = error == std::string::npos ? "failed (" + o.describe(timeout) + ")"
                                           : output.substr(error, output.find('\n', error) - error);
}

// What a grader-side path is called in the feedback (results.json, junit.xml; OUT/logs keep the
// real ones): the student's files by their lesson's name, the tree as "grader", the work folder
// as "work", the reference build's sources relative to the repository. Longest path first, so a
// path inside another is named by the inner one.
std::vector<std::pair<std::string, std::string>> neutralNames(const Grading& g, const std::string& lesson,
                                                              size_t tests) {
    const fs::path dir = g.work / lesson.substr(0, 2);
    std::vector<std::pair<fs::path, std::string>> named = {{dir / "src", lesson}, {dir / "build", "build"},
                                                           {dir, "work"},         {g.work, "work"},
                                                           {g.tree, "grader"},    {g.submission, "submission"}};
    for (size_t i = 0; i < tests; ++i) named.push_back({dir / ("run-" + std::to_string(i)), "."});
    std::ifstream where(g.tree / "reference-paths.txt");  // cmake/grader_tree.cmake: source, build
    std::string source, build;
    if (std::getline(where, source) && !source.empty()) named.push_back({source, "."});
    if (std::getline(where, build) && !build.empty()) named.push_back({build, "build"});
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& [path, name] : named) {
        std::error_code ec;
        const fs::path real = fs::weakly_canonical(path, ec);
        for (const fs::path& p : {path, real})
            if (!p.empty() && p.string().size() > 1) {
                out.push_back({p.string() + "/", name == "." ? "" : name + "/"});
                out.push_back({p.string(), name});
            }
    }
    std::stable_sort(out.begin(), out.end(),
                     [](const auto& a, const auto& b) { return a.first.size() > b.first.size(); });
    return out;
}

std::string neutral(std::string text, const std::vector<std::pair<std::string, std::string>>& names) {
    for (const auto& [from, to] : names)
        for (size_t p = 0; (p = text.find(from, p)) != std::string::npos; p += to.size())
            text.replace(p, from.size(), to);
    return text;
}

std::vector<TestResult> gradeLessonWithPaths(const Grading& g, const std::string& lesson, std::string& note);

}  // namespace

std::vector<TestResult> gradeLesson(const Grading& g, const std::string& lesson, std::string& note) {
    std::string raw;
    std::vector<TestResult> results = gradeLessonWithPaths(g, lesson, raw);
    const auto names = neutralNames(g, lesson, results.size());
    for (TestResult& r : results) {
        r.message = neutral(r.message, names);
        r.output = neutral(r.output, names);
    }
    note += neutral(raw, names);
    return results;
}

View treeView(const Grading& g, const std::string& lesson) {
    const std::string nn = lesson.substr(0, 2);
    View v;
    for (const char* p : {"include", "rules", "lib/framework.a", "lib/test_support.a", "lib/test_main.o"})
        v.readOnly.push_back((g.tree / p).string());
    for (const auto& e : fs::directory_iterator(g.tree / "lib")) {
        if (!e.is_directory()) continue;
        if (fs::is_directory(e.path() / "plumbing")) v.readOnly.push_back((e.path() / "plumbing").string());
        if (e.path().filename() != nn) v.readOnly.push_back((e.path() / "reference").string());
    }
    v.readOnly.push_back((g.tree / "lib" / nn / "tests").string());
    return v;
}

namespace {

// gradeLesson, with the grader's real paths in what it says.
std::vector<TestResult> gradeLessonWithPaths(const Grading& g, const std::string& lesson, std::string& note) {
    const std::string nn = lesson.substr(0, 2);
    std::vector<TestResult> results;
    for (const std::string& name : lines(g.tree / "tests" / (lesson + ".txt"))) {
        TestResult r;
        r.lesson = lesson;
        r.name = name;
        r.points = pointsOf(name);
        results.push_back(r);
    }
    auto failAll = [&](const std::string& why) {
        for (TestResult& r : results) r.message = why;
        return results;
    };

    // 1. The submission's files of this lesson, copied: never through a link, never a plumbing file.
    const fs::path dir = g.work / nn, src = dir / "src", build = dir / "build";
    fs::create_directories(src);
    fs::permissions(dir, fs::perms::owner_all | fs::perms::others_exec | fs::perms::group_exec);
    fs::permissions(src, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec | fs::perms::others_read |
                             fs::perms::others_exec);
    makeWritable(build, g.sandbox);
    const fs::path from = g.submission / lesson;
    std::string sources;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(from, ec)) {
        const std::string name = e.path().filename().string(), ext = e.path().extension().string();
        if (ext != ".cpp" && ext != ".h") continue;
        if (e.is_symlink()) note += "left out " + name + ": a symbolic link\n";
        else if (!e.is_regular_file()) note += "left out " + name + ": not a regular file\n";
        else if (!plainName(name)) note += "left out " + name + ": a file name with unusual characters\n";
        else if (e.file_size() > (1 << 20)) note += "left out " + name + ": larger than 1 MiB\n";
        else if (ext == ".cpp" && fs::exists(g.tree / "lib" / nn / "plumbing" / (e.path().stem().string() + ".o")))
            note += "left out " + name + ": the lesson's own file of that name is used\n";
        else {
            fs::copy_file(e.path(), src / name, fs::copy_options::overwrite_existing);
            fs::permissions(src / name, kReadable);
            if (ext == ".cpp") sources += (sources.empty() ? "" : " ") + name;
        }
    }
    if (ec) return note += "no folder " + from.string() + "\n", failAll("no folder " + lesson + " in the submission");
    if (sources.empty()) return note += "no .cpp file in " + from.string() + "\n", failAll("no .cpp file to build");

    // 2. The build, in the sandbox.
    Step make;
    make.argv = {findProgram("make"),
                 "-r",
                 "-f",
                 (g.tree / "rules" / "lesson.mk").string(),
                 "-j" + std::to_string(g.jobs),
                 "TREE=" + g.tree.string(),
                 "LESSON=" + nn,
                 "SRCDIR=" + src.string(),
                 "SOURCES=" + sources,
                 "lesson_tests"};
    make.env = environment(build);
    make.cwd = build.string();
    make.log = (g.logs / (nn + "-build.log")).string();
    make.timeout = g.buildTimeout;
    make.limits = true;
    View view = treeView(g, lesson);
    view.readOnly.push_back(src.string());
    view.writable.push_back(build.string());
    const Outcome built = run(g.sandbox.wrap(make, view));
    const fs::path program = build / "lesson_tests";
    if (!built.ok() || fs::is_symlink(program) || !fs::is_regular_file(program)) {
        const std::string why = built.timedOut ? "the build " + built.describe(g.buildTimeout)
                                               : "the lesson did not build (" + built.describe(0) + ")";
        note += why + "; the end of its log:\n" + tail(readText(make.log), 30);
        return failAll(why);
    }

    // 3. Each graded test alone, in the sandbox.
    std::vector<Step> steps;
    for (size_t i = 0; i < results.size(); ++i) {
        const fs::path scratch = dir / ("run-" + std::to_string(i));
        makeWritable(scratch, g.sandbox);
        Step t;
        t.argv = {program.string(), "--test-case=" + doctestFilter(results[i].name)};
        t.env = environment(scratch);
        t.env.push_back("PATHSPACE_TEST_SOURCE_DIR=" + (g.tree / "data").string());
        t.env.push_back("PATHSPACE_TEST_OUTPUT_DIR=" + scratch.string());
        t.cwd = scratch.string();
        t.log = (g.logs / (nn + "-test-" + std::to_string(i) + ".log")).string();
        t.timeout = g.testTimeout;
        t.limits = true;
        steps.push_back(g.sandbox.wrap(t, View{{(g.tree / "data").string(), program.string()}, {scratch.string()}}));
    }
    const std::vector<Outcome> outcomes = runAll(steps, g.jobs);
    for (size_t i = 0; i < results.size(); ++i)
        judge(results[i], outcomes[i], readText(steps[i].log), g.testTimeout, g.sandbox.on());
    return results;
}

}  // namespace

}  // namespace grade
