// grade: the course's autograder (README, "The autograder"). Scores a submission lesson by
// lesson, each lesson IN ISOLATION: the lesson under test from the submission, every other
// lesson from the reference, prebuilt.
//
//   grade --prepare DIR [--source SRC] [--jobs N]
//   grade [--tree DIR] [--submission DIR] [--lessons 0,1|all] [--out OUT] [--timeout S]
//         [--build-timeout S] [--jobs N] [--no-sandbox|--sandbox-or-none] [--no-object-check]
//         [--keep-work] [--expect zero|full] [--note TEXT]
//   grade --junit FILE [--source SRC] [--lessons ...] [--out OUT] [--expect zero|full]
//   grade --check-reference [--tree DIR] [--lessons ...]
//   grade --check-objects LESSON FILE.o... [--tree DIR]
//
// --prepare builds the reference once (in DIR/build) and assembles the prepared tree in DIR
// (cmake/grader.cmake: headers, the framework, every lesson's reference, plumbing and tests as
// objects, the data tests read, the build rules; no solution source). Every reference build makes
// one as a by-product in BUILD/grader, the default --tree.
// Grading compiles only the submission's files of each lesson, checks the objects (objcheck.h),
// links them with the tree and runs each graded test alone, all in a sandbox with time limits
// (lesson.h, sandbox.h, process.h); a test's verdict comes from the grader's result channel
// (verdict.h), never from what it printed. The work folder is removed however grading ends.
// With --junit nothing is built or run: the graded tests are scored from a CTest JUnit report
// (CI proves this way that the reference scores full marks and the skeleton zero).
// Writes OUT/results.json (Gradescope), OUT/junit.xml and OUT/logs/ (every step's output), and
// prints a score table. Exit status: 0; 1 when --expect is not met; 2 for a bad command line;
// 3 when there is no working sandbox and neither --no-sandbox nor --sandbox-or-none was given, or
// no objdump and
// --no-object-check was not given; 128 + N when signal N stopped it.
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "lesson.h"
#include "objcheck.h"
#include "process.h"
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
    "             [--build-timeout S] [--jobs N] [--no-sandbox|--sandbox-or-none] [--no-object-check]\n"
    "             [--keep-work] [--expect zero|full] [--note TEXT]\n"
    "       grade --junit FILE [--source SRC] [--lessons 0,1|all] [--out OUT] [--expect zero|full]\n"
    "       grade --check-reference [--tree DIR] [--lessons 0,1|all]\n"
    "       grade --check-objects LESSON FILE.o... [--tree DIR]\n"
    "--prepare DIR builds the reference once and puts in DIR what grading needs (no solution source).\n"
    "Grading scores each lesson in isolation: that lesson from the submission (DIR holds lesson\n"
    "folders like assignments/, the default), every other lesson from the prepared tree (--tree,\n"
    "default: this build's grader/). Only the submission's files are compiled; the build and each\n"
    "test run in a sandbox (bubblewrap: no network, nothing but the submission's copy and the tree;\n"
    "as nobody when root). --no-sandbox runs them unprotected, as you (for trusted code only);\n"
    "--sandbox-or-none uses the sandbox where bubblewrap works and otherwise grades without it, saying\n"
    "so on stderr and in results.json (a throw-away container that cannot make namespaces).\n"
    "PATHSPACE_GRADE_BWRAP=PROGRAM: the bubblewrap to use (default: bwrap on PATH).\n"
    "Before linking, the object check refuses a lesson whose objects use what graded code may not\n"
    "(files, system calls, process control, the test framework...) or hold a system-call\n"
    "instruction; --no-object-check skips it (the scores then rest on the result channel alone).\n"
    "A test passes only when the harness's records on the grader's channel say so.\n"
    "--timeout S limits each graded test (default 120), --build-timeout S the build of a lesson\n"
    "(default 300): a test stopped scores 0 ('timed out after S s'), a build stopped scores 0 for\n"
    "the lesson. --jobs N compiles and runs N at a time (default 2). Writes OUT/results.json\n"
    "(Gradescope), OUT/junit.xml and OUT/logs/ (default OUT: ./grade). --keep-work keeps the\n"
    "work folders (their path is printed). --note TEXT goes first in results.json's output (what a\n"
    "wrapper such as the Gradescope package has to say about the upload).\n"
    "--junit FILE scores the graded tests from an existing CTest JUnit report instead of building.\n"
    "--expect zero|full: exit 1 unless every graded test failed / passed.\n"
    "--check-reference runs the object check on every lesson's reference objects, --check-objects on\n"
    "the given objects as lesson LESSON's (00 or 00-rays); exit 1 if it refuses anything.\n"
    "Exit status 3: no working sandbox (install bubblewrap, or --no-sandbox), or no objdump (install\n"
    "binutils, or --no-object-check). SIGINT or SIGTERM stops grading, work folder removed.\n";

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

// The object check on `objects` as if they were a submission of `lesson` (objdump, run here:
// they are trusted files); prints the findings and returns how many there are.
size_t checkObjectFiles(const fs::path& tree, const std::string& lesson, const std::vector<fs::path>& objects) {
    const fs::path log = fs::temp_directory_path() / ("grade-check-" + std::to_string(getpid()) + ".txt");
    std::vector<std::pair<std::string, ElfObject>> parsed;
    Step dis;
    dis.argv = {findProgram("objdump"), "-d", "-z", "-w"};
    for (const fs::path& o : objects) {
        // "rays.o" (the tree's) or "rays.cpp.o" (CMake's): "rays.cpp"
        const std::string name = o.stem().extension() == ".cpp" ? o.stem().string() : o.stem().string() + ".cpp";
        try {
            parsed.push_back({name, readElf(readText(o))});
        } catch (const std::exception& e) {
            std::cout << lesson << ": " << o.string() << ": " << e.what() << "\n";
            return 1;
        }
        dis.argv.push_back(fs::absolute(o).string());
    }
    dis.env = {"PATH=/usr/bin:/bin", "LC_ALL=C"};
    dis.log = log.string();
    const Outcome o = run(dis);
    std::vector<Finding> findings = checkObjects(parsed, courseSymbols(tree, lesson));
    if (!o.ok()) findings.push_back({"", "objdump failed: " + o.describe(0)});
    std::string text = readText(log);
    // objdump names each file by the path it was given: by its own name here, as in grading.
    for (const fs::path& f : objects) text = neutral(text, {{fs::absolute(f).parent_path().string() + "/", ""}});
    const std::vector<Finding> more = checkDisassembly(text);
    findings.insert(findings.end(), more.begin(), more.end());
    std::error_code ec;
    fs::remove(log, ec);
    std::cout << lesson << ": " << parsed.size() << " objects, "
              << (findings.empty() ? "nothing refused" : std::to_string(findings.size()) + " findings:") << "\n";
    for (const Finding& f : findings) std::cout << "  " << f.file << ": " << f.what << "\n";
    return findings.size();
}

// grade --check-reference: the object check on every lesson's reference objects, as if they were
// a submission (CI: the check refuses nothing the course's own solutions need).
int checkReference(const fs::path& tree, const std::vector<std::string>& lessons) {
    size_t findings = 0;
    for (const std::string& lesson : lessons) {
        std::vector<fs::path> objects;
        for (const auto& e : fs::directory_iterator(tree / "lib" / lesson.substr(0, 2) / "reference"))
            if (e.path().extension() == ".o") objects.push_back(e.path());
        std::sort(objects.begin(), objects.end());
        findings += checkObjectFiles(tree, lesson, objects);
    }
    return findings ? 1 : 0;
}

// Writes results.json and junit.xml (with `junit`), then checks --expect: the exit status.
int finish(const std::vector<TestResult>& results, const std::map<std::string, std::string>& notes, const fs::path& out,
           bool junit, double seconds, const std::string& expect) {
    try {
        fs::create_directories(out);
        writeReport(results, notes, out, junit, seconds);
    } catch (const std::exception& e) {
        std::cerr << "grade: " << e.what() << "\n";
        return 1;
    }
    std::cerr << "grade: wrote " << (out / "results.json").string()
              << (junit ? " and " + (out / "junit.xml").string() : "") << "\n";
    if (expect.empty()) return 0;
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
    return 0;
}

volatile std::sig_atomic_t stopSignal = 0;
extern "C" void onStopSignal(int s) { stopSignal = s; }

// Makes the work folder, runs `grading` on it in a child process (the worker) and, however the
// worker ends (its own exit, a crash, a signal to either), kills every process left of it and
// removes the folder (unless `keep`); returns the worker's exit status, or ends by the signal
// that stopped the grading. Only SIGKILL to this process itself leaves the folder behind (the
// worker and its steps then die with it: PR_SET_PDEATHSIG).
int guarded(bool keep, const std::function<int(const fs::path&)>& grading) {
    struct sigaction sa {};
    sa.sa_handler = onStopSignal;  // no SA_RESTART: waitpid returns EINTR
    sigemptyset(&sa.sa_mask);
    const int stops[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};
    for (int s : stops) sigaction(s, &sa, nullptr);
    std::string work = (fs::temp_directory_path() / "pathspace-grade-XXXXXX").string();
    if (!mkdtemp(work.data())) {
        std::cerr << "grade: cannot make a work folder in " << fs::temp_directory_path().string() << "\n";
        return 1;
    }
    fs::permissions(work, fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec);
    prctl(PR_SET_CHILD_SUBREAPER, 1);  // what the worker's steps leave behind comes back here
    std::fflush(nullptr);
    const pid_t guard = getpid();
    const pid_t worker = stopSignal ? -1 : fork();
    if (worker == 0) {
        for (int s : stops) signal(s, SIG_DFL);
        prctl(PR_SET_PDEATHSIG, SIGKILL);
        if (getppid() != guard) _exit(1);
        int status = 1;
        try {
            status = grading(work);
        } catch (const std::exception& e) { std::cerr << "grade: " << e.what() << "\n"; }
        std::exit(status);
    }
    int status = 0;
    while (worker > 0) {
        if (stopSignal) kill(worker, SIGKILL);
        const pid_t r = waitpid(worker, &status, WNOHANG);
        if (r == worker || (r < 0 && errno != EINTR)) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    reapEveryChild();
    std::error_code ec;
    if (!keep) fs::remove_all(work, ec);
    if (stopSignal) {
        std::cerr << "grade: stopped by signal " << stopSignal << " (" << strsignal(stopSignal) << "); "
                  << (keep ? "work folder kept in " + work : std::string("work folder removed")) << "\n";
        signal(stopSignal, SIG_DFL);
        raise(stopSignal);
        return 128 + stopSignal;
    }
    if (worker < 0 || WIFSIGNALED(status)) {
        std::cerr << "grade: the grading died (" << (worker < 0 ? "fork failed" : strsignal(WTERMSIG(status))) << "); "
                  << (keep ? "work folder kept in " + work : std::string("work folder removed")) << "\n";
        return worker < 0 ? 1 : 128 + WTERMSIG(status);
    }
    return WEXITSTATUS(status);
}

}  // namespace

int main(int argc, char** argv) {
    const auto started = std::chrono::steady_clock::now();
    fs::path source = PATHSPACE_SOURCE_DIR, tree = PATHSPACE_GRADER_TREE;
    fs::path submission = source / "assignments", out = "grade", junitIn, prepareDir;
    std::string lessonsArg = "all", expect, note;
    int timeout = 120, buildTimeout = 300, jobs = 2;
    bool noSandbox = false, sandboxOrNone = false, keepWork = false, noObjectCheck = false, checkRef = false;
    std::string checkLesson;
    std::vector<fs::path> checkFiles;
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
        else if (a == "--sandbox-or-none") sandboxOrNone = true;
        else if (a == "--keep-work") keepWork = true;
        else if (a == "--no-object-check") noObjectCheck = true;
        else if (a == "--check-reference") checkRef = true;
        else if (a == "--check-objects") {
            checkLesson = value();
            while (i + 1 < argc && std::string(argv[i + 1]).rfind("--", 0) != 0) checkFiles.push_back(argv[++i]);
            if (checkFiles.empty()) usageError("--check-objects needs a lesson and object files");
        } else if (a == "--note") note = value();
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
    if (!fromReport && !fs::is_directory(tree / "lib" / "main")) {
        std::cerr << "grade: " << tree.string()
                  << " was prepared by an older grader (no lib/main/: the tests' main with the result channel); "
                     "prepare it again (grade --prepare DIR, or build target grader_tree)\n";
        return 2;
    }
    if (lessons.empty()) {
        std::cerr << "grade: no lesson matches '" << lessonsArg << "'\n";
        return 2;
    }
    if (fromReport && !fs::is_regular_file(junitIn)) {
        std::cerr << "grade: " << junitIn.string() << ": no such JUnit report\n";
        return 2;
    }

    out = fs::absolute(out);
    if (checkRef) return checkReference(tree, lessons);
    if (!checkLesson.empty()) {
        for (const std::string& l : lessons)
            if (l == checkLesson || l.substr(0, 2) == checkLesson) return checkObjectFiles(tree, l, checkFiles) ? 1 : 0;
        usageError("--check-objects: no lesson '" + checkLesson + "' in the tree");
    }
    std::map<std::string, std::string> notes;
    notes[""] = note;
    if (fromReport) {  // score the report, nothing to build
        std::vector<TestResult> results;
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
        // execution_time: for a report, the time its tests took.
        double seconds = 0;
        for (const TestResult& r : results) seconds += r.seconds;
        return finish(results, notes, out, false, seconds, expect);
    }
    Grading g;
    g.tree = tree;
    g.submission = submission;
    g.testTimeout = timeout;
    g.buildTimeout = buildTimeout;
    g.jobs = jobs;
    g.keepWork = keepWork;
    g.objectCheck = !noObjectCheck;
    if (!noSandbox) {
        std::string why;
        g.sandbox = Sandbox::probe(treeView(g, lessons.front()), why);
        if (!g.sandbox.on() && sandboxOrNone) {
            std::cerr << "grade: no sandbox: " << why
                      << ".\ngrade: --sandbox-or-none: grading WITHOUT a sandbox; the submission runs as this user\n";
            notes[""] += std::string(notes[""].empty() ? "" : "\n") +
                         "graded without a sandbox (bubblewrap cannot run in this container)";
        } else if (!g.sandbox.on()) {
            std::cerr << "grade: no sandbox: " << why
                      << ".\ngrade: install it (apt-get install bubblewrap), or give --no-sandbox to run the "
                         "submission unprotected, as you (trusted code only)\n";
            return 3;
        }
        if (g.sandbox.on())
            std::cerr << "grade: sandbox: bwrap" << (g.sandbox.unprivileged() ? ", as nobody" : "") << "\n";
    } else std::cerr << "grade: --no-sandbox: the submission runs as you and can read and change your files\n";
    if (g.objectCheck && findProgram("objdump").empty()) {
        std::cerr << "grade: no objdump (Debian package binutils) for the object check: install it, or give "
                     "--no-object-check (the result channel alone then guards the scores)\n";
        return 3;
    }
    if (!g.objectCheck) std::cerr << "grade: --no-object-check: submission code may call anything\n";
    fs::create_directories(out);
    g.logs = out / "logs";
    fs::remove_all(g.logs);
    fs::create_directories(g.logs);
    // The work folder: made and removed by a guard process that the grading runs under, so that
    // it goes whichever way the grading ends (a signal, a crash of the grader included).
    return guarded(keepWork, [&](const fs::path& work) {
        g.work = work;
        std::vector<TestResult> results;
        for (const std::string& lesson : lessons) {
            std::cerr << "grade: lesson " << lesson << "\n";
            std::vector<TestResult> r = gradeLesson(g, lesson, notes[lesson]);
            results.insert(results.end(), r.begin(), r.end());
        }
        // Every step has ended, with every process it started (process.h): nothing but the grader
        // writes OUT from here on.
        if (keepWork) std::cerr << "grade: work folders kept in " << work.string() << "\n";
        // execution_time: the grading's wall time.
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        return finish(results, notes, out, true, seconds, expect);
    });
}
