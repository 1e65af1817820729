// Grading one lesson from the prepared tree (lesson.h).
#include "lesson.h"

#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

#include "grade_channel.h"
#include "objcheck.h"
#include "verdict.h"

namespace fs = std::filesystem;

namespace grade {

namespace {

// A file name the build rules can take as it is: letters, digits, '_', '.', '+', '-', not
// beginning with '.', '+' or '-' (no spaces, quotes, '$', no option).
bool plainName(const std::string& n) {
    auto word = [](char c) {
        return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
    };
    return !n.empty() && word(n[0]) &&
           std::all_of(n.begin(), n.end(), [&](char c) { return word(c) || c == '.' || c == '+' || c == '-'; });
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

// The end of a long text (a build log), whole lines, at most `most` bytes.
std::string tail(const std::string& text, int n, size_t most) {
    size_t p = text.size();
    for (int i = 0; i <= n && p != std::string::npos && p > 0; ++i) p = text.rfind('\n', p - 1);
    std::string t = p == std::string::npos || p == 0 ? text : text.substr(p + 1);
    return t.size() > most ? "[...]" + t.substr(t.size() - most) : t;
}

// The environment of every step: nothing of the grader's.
std::vector<std::string> environment(const fs::path& home) {
    return {"PATH=/usr/bin:/bin", "HOME=" + home.string(), "TMPDIR=" + home.string(), "LC_ALL=C", "MAKEFLAGS="};
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
    // Longest first; a total order, so that std::sort's result is one (stable_sort trips clang 19's
    // deprecation warning inside libstdc++ 12).
    std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) {
        return a.first.size() != b.first.size() ? a.first.size() > b.first.size() : a < b;
    });
    return out;
}

// The log cap of each of `steps` steps sharing `budget` bytes.
std::uint64_t share(std::uint64_t budget, size_t steps) {
    return std::clamp<std::uint64_t>(budget / std::max<size_t>(steps, 1), kMinStepLog, kStepLog);
}

std::uint64_t fileSize(const fs::path& p) {
    std::error_code ec;
    const std::uintmax_t n = fs::file_size(p, ec);
    return ec ? 0 : std::uint64_t(n);
}

std::vector<TestResult> gradeLessonWithPaths(Grading& g, const std::string& lesson, std::string& note);

}  // namespace

std::string clip(const std::string& s) {
    const size_t max = 16 << 10;
    if (s.size() <= max) return s;
    return s.substr(0, max / 4) + "\n[... " + std::to_string(s.size() - max) + " bytes left out ...]\n" +
           s.substr(s.size() - 3 * max / 4);
}

std::string neutral(std::string text, const std::vector<std::pair<std::string, std::string>>& names) {
    for (const auto& [from, to] : names)
        for (size_t p = 0; (p = text.find(from, p)) != std::string::npos; p += to.size())
            text.replace(p, from.size(), to);
    return text;
}

std::vector<TestResult> gradeLesson(Grading& g, const std::string& lesson, std::string& note) {
    std::string raw;
    std::vector<TestResult> results = gradeLessonWithPaths(g, lesson, raw);
    const auto names = neutralNames(g, lesson, results.size());
    for (TestResult& r : results) {
        r.message = neutral(r.message, names);
        r.output = neutral(r.output, names);
    }
    raw = neutral(raw, names);
    note += raw.size() > kNoteBytes ? raw.substr(0, kNoteBytes) + "\n[... the rest is in the grader's logs]\n" : raw;
    if (!g.keepWork) {
        std::error_code ec;
        fs::remove_all(g.work / lesson.substr(0, 2), ec);
    }
    return results;
}

View treeView(const Grading& g, const std::string& lesson) {
    const std::string nn = lesson.substr(0, 2);
    View v;
    for (const char* p : {"include", "rules", "lib/framework.a", "lib/test_support.a", "lib/main"})
        v.readOnly.push_back((g.tree / p).string());
    // Shared libraries from outside /usr (cmake/grader_tree.cmake), linked and loaded from there.
    if (fs::is_directory(g.tree / "lib" / "runtime")) v.readOnly.push_back((g.tree / "lib" / "runtime").string());
    for (const auto& e : fs::directory_iterator(g.tree / "lib")) {
        if (!e.is_directory() || e.path().filename() == "main" || e.path().filename() == "runtime") continue;
        if (fs::is_directory(e.path() / "plumbing")) v.readOnly.push_back((e.path() / "plumbing").string());
        if (e.path().filename() != nn) v.readOnly.push_back((e.path() / "reference").string());
    }
    v.readOnly.push_back((g.tree / "lib" / nn / "tests").string());
    return v;
}

namespace {

// gradeLesson, with the grader's real paths in what it says.
std::vector<TestResult> gradeLessonWithPaths(Grading& g, const std::string& lesson, std::string& note) {
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
    // OUT/logs: this lesson's share, what it has written so far.
    const std::uint64_t lessonBudget = std::min(kLessonLogs, g.logBudget);
    std::uint64_t written = 0;
    auto logged = [&](const std::string& log) {
        const std::uint64_t n = fileSize(log);
        written += n;
        g.logBudget -= std::min(g.logBudget, n);
    };
    auto leftForLogs = [&] { return std::min(lessonBudget - std::min(lessonBudget, written), g.logBudget); };

    // 1. The submission's files of this lesson, copied: never through a link, never a plumbing file.
    const fs::path dir = g.work / nn, src = dir / "src", build = dir / "build";
    fs::create_directories(src);
    fs::permissions(dir, fs::perms::owner_all | fs::perms::others_exec | fs::perms::group_exec);
    fs::permissions(src, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec | fs::perms::others_read |
                             fs::perms::others_exec);
    makeWritable(build, g.sandbox);
    const fs::path from = g.submission / lesson;
    std::vector<fs::path> entries;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(from, ec)) entries.push_back(e.path());
    std::sort(entries.begin(), entries.end());
    std::vector<std::string> sources;
    size_t copied = 0;
    for (const fs::path& e : entries) {
        const std::string name = e.filename().string(), ext = e.extension().string();
        if (ext != ".cpp" && ext != ".h") continue;
        std::error_code fe;
        if (fs::is_symlink(fs::symlink_status(e, fe))) note += "left out " + name + ": a symbolic link\n";
        else if (!fs::is_regular_file(fs::symlink_status(e, fe))) note += "left out " + name + ": not a regular file\n";
        else if (!plainName(name)) note += "left out " + name + ": a file name with unusual characters\n";
        else if (fileSize(e) > kMaxFileBytes) note += "left out " + name + ": larger than 1 MiB\n";
        else if (ext == ".cpp" && fs::exists(g.tree / "lib" / nn / "plumbing" / (e.stem().string() + ".o")))
            note += "left out " + name + ": the lesson's own file of that name is used\n";
        else if (copied == kMaxFiles)
            note +=
                "left out " + name + ": a lesson's folder may hold at most " + std::to_string(kMaxFiles) + " files\n";
        else {
            fs::copy_file(e, src / name, fs::copy_options::overwrite_existing);
            fs::permissions(src / name, kReadable);
            ++copied;
            if (ext == ".cpp") sources.push_back(name);
        }
    }
    if (ec) return note += "no folder " + from.string() + "\n", failAll("no folder " + lesson + " in the submission");
    if (sources.empty()) return note += "no .cpp file in " + from.string() + "\n", failAll("no .cpp file to build");
    std::string sourceList;
    std::vector<std::string> objects;
    for (const std::string& s : sources) {
        objects.push_back(s.substr(0, s.size() - 4) + ".o");
        sourceList += (sourceList.empty() ? "" : " ") + s;
    }

    // 2. Compile, in the sandbox; 4. link (after the check), the same way.
    View buildView = treeView(g, lesson);
    buildView.readOnly.push_back(src.string());
    buildView.writable.push_back(build.string());
    auto make = [&](const std::string& target, const std::string& log) {
        Step m;
        m.argv = {findProgram("make"),
                  "-r",
                  "-f",
                  (g.tree / "rules" / "lesson.mk").string(),
                  "-j" + std::to_string(g.jobs),
                  "TREE=" + g.tree.string(),
                  "LESSON=" + nn,
                  "SRCDIR=" + src.string(),
                  "SOURCES=" + sourceList,
                  target};
        m.env = environment(build);
        m.cwd = build.string();
        m.log = (g.logs / log).string();
        m.logCap = share(leftForLogs(), 1);
        m.timeout = g.buildTimeout;
        m.limits = true;
        m.fileSizeLimit = kBuildFileBytes;
        const Outcome o = run(g.sandbox.wrap(m, buildView));
        logged(m.log);
        if (!o.logError.empty()) note += "grade: " + o.logError + "\n";
        if (o.ok()) return std::string();
        const std::string why =
            o.timedOut ? "the build " + o.describe(g.buildTimeout) : "the lesson did not build (" + o.describe(0) + ")";
        note += why + "; the end of its log:\n" + tail(readText(m.log), 30, 4096);
        return why;
    };
    if (std::string why = make("objects", nn + "-build.log"); !why.empty()) return failAll(why);

    // 3. The object check: objdump's text of the objects (a sandboxed step), then the grader's rules.
    if (g.objectCheck) {
        Step dis;
        dis.argv = {findProgram("objdump"), "-d", "-z", "-w"};
        dis.argv.insert(dis.argv.end(), objects.begin(), objects.end());
        dis.env = environment(build);
        dis.cwd = build.string();
        dis.log = (dir / "disassembly.txt").string();
        dis.logCap = kDisassemblyBytes;
        dis.logTail = false;
        dis.timeout = g.buildTimeout;
        dis.limits = true;
        const Outcome o = run(g.sandbox.wrap(dis, View{{build.string()}, {}, {}}));
        std::vector<Finding> findings;
        if (!o.ok() || o.outputBytes > kDisassemblyBytes) {
            findings.push_back({"", "objdump could not disassemble the lesson's code (" +
                                        (o.ok() ? "more than 64 MiB of it" : o.describe(g.buildTimeout)) + ")"});
        } else {
            try {
                std::vector<std::pair<std::string, ElfObject>> parsed;
                for (size_t i = 0; i < objects.size(); ++i)
                    parsed.push_back({sources[i], readElf(readText(build / objects[i]))});
                findings = checkObjects(parsed, courseSymbols(g.tree, lesson));
                std::vector<Finding> more = checkDisassembly(readText(dis.log));
                findings.insert(findings.end(), more.begin(), more.end());
            } catch (const std::exception& e) {
                findings.push_back({"", std::string("the grader cannot read the lesson's objects: ") + e.what()});
            }
        }
        if (!findings.empty()) {
            note += "refused by the object check (README, \"The autograder\": what graded code may use):\n";
            std::map<std::string, size_t> perFile;  // at most four findings of a file, then how many more
            for (const Finding& f : findings) {
                const size_t k = ++perFile[f.file];
                if (k <= 4) note += "  " + (f.file.empty() ? "" : lesson + "/" + f.file + ": ") + f.what + "\n";
            }
            for (const auto& [file, n] : perFile)
                if (n > 4) note += "  " + lesson + "/" + file + ": and " + std::to_string(n - 4) + " more\n";
            const Finding& f = findings.front();
            return failAll("refused by the object check: " + (f.file.empty() ? "" : lesson + "/" + f.file + " ") +
                           f.what);
        }
    }
    if (std::string why = make("lesson_tests", nn + "-link.log"); !why.empty()) return failAll(why);
    const fs::path program = build / "lesson_tests";
    if (fs::is_symlink(program) || !fs::is_regular_file(program))
        return failAll("the lesson did not build (no test program)");

    // 5. Each graded test alone, in the sandbox, with the result channel.
    std::vector<Step> steps;
    const std::uint64_t testLog = share(leftForLogs(), results.size());
    for (size_t i = 0; i < results.size(); ++i) {
        const fs::path scratch = dir / ("run-" + std::to_string(i));
        makeWritable(scratch, g.sandbox);
        Step t;
        t.argv = {program.string(), "--test-case=" + doctestFilter(results[i].name)};
        t.env = environment(scratch);
        t.env.push_back("PATHSPACE_TEST_SOURCE_DIR=" + (g.tree / "data").string());
        t.env.push_back("PATHSPACE_TEST_OUTPUT_DIR=" + scratch.string());
        t.env.push_back(std::string(ps::gradechannel::kEnv) + "=" + std::to_string(ps::gradechannel::kFd));
        // The tests' main() would otherwise run itself again to set it (framework/passive_wait.h),
        // and the channel, close-on-exec once its token is taken, would not follow.
        t.env.push_back("OMP_WAIT_POLICY=PASSIVE");
        t.cwd = scratch.string();
        t.log = (g.logs / (nn + "-test-" + std::to_string(i) + ".log")).string();
        t.logCap = testLog;
        t.timeout = g.testTimeout;
        t.limits = true;
        t.channel = true;
        View view{{(g.tree / "data").string(), program.string()}, {}, {scratch.string()}};
        view.scratchBytes = kScratchBytes;
        steps.push_back(g.sandbox.wrap(t, view));
    }
    const std::vector<Outcome> outcomes = runAll(steps, g.jobs);
    for (size_t i = 0; i < results.size(); ++i) {
        const Verdict v = judge(outcomes[i], results[i].name, g.testTimeout, g.sandbox.on());
        TestResult& r = results[i];
        r.passed = v.passed;
        r.timedOut = v.timedOut;
        r.message = v.message;
        r.seconds = outcomes[i].seconds;
        if (!r.passed) r.output = clip(readText(steps[i].log));
        logged(steps[i].log);
        if (!outcomes[i].logError.empty()) note += "grade: " + outcomes[i].logError + "\n";
    }
    return results;
}

}  // namespace

}  // namespace grade
