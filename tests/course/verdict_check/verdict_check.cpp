// The grader's verdict (tools/grade/verdict.h) on the records a test's run can leave on the
// result channel: the one honest pass, and each way a run that did not pass can look like one
// (a fake summary leaves no record, a forgery has no token, an early exit no end...). Prints
// one line per case; exit status 1 when a verdict or its message is not the expected one.
#include <cstdio>
#include <string>
#include <vector>

#include "verdict.h"

using grade::Outcome;

namespace {

const std::string T = "0123456789abcdef0123456789abcdef";
const std::string kName = "rays: a test [1 pt]";

Outcome run(int exitCode, std::vector<std::string> records) {
    Outcome o;
    o.exitCode = exitCode;
    o.token = T;
    for (std::string& r : records) o.channel.push_back(r[0] == '~' ? T + " " + r.substr(1) : r);
    return o;
}

const std::vector<std::string> kPass = {"~start\n" + kName, "~end 4 0 0 0 1", "~run 1 0 4 0", "~exit 0"};

}  // namespace

int main() {
    struct Case {
        const char* what;
        Outcome o;
        bool passes;
        std::string says;  // part of the message
    };
    Outcome crashed = run(0, kPass), timedOut = run(0, {"~start\n" + kName}), overflow = run(0, kPass);
    crashed.signal = 11;
    timedOut.timedOut = true;
    overflow.channelOverflow = true;
    std::vector<std::string> renamed = kPass, reordered = kPass, twice = kPass, badNumber = kPass;
    renamed[0] = "~start\nrays: another test [1 pt]";
    std::swap(reordered[2], reordered[3]);
    twice.insert(twice.begin() + 2, {"~start\n" + kName, "~end 1 0 0 0 1"});
    badNumber[1] = "~end 4 0x0 0 0 1";
    const std::vector<Case> cases = {
        {"the honest pass", run(0, kPass), true, ""},
        {"a fake summary and exit 0: no record", run(0, {}), false, "ended before the test started (exit status 0)"},
        {"_exit(0) inside the test", run(0, {"~start\n" + kName}), false,
         "ended before the test finished (exit status 0)"},
        {"exit after the test, before doctest's summary", run(0, {"~start\n" + kName, "~end 4 0 0 0 1"}), false,
         "before doctest's summary"},
        {"main() never returned", run(0, {"~start\n" + kName, "~end 4 0 0 0 1", "~run 1 0 4 0"}), false,
         "did not return from main()"},
        {"a failed assertion",
         run(1, {"~start\n" + kName, "~end 4 1 1 1 0\nt.cpp:3: ERROR: CHECK( a ) is NOT correct!", "~run 1 1 4 1",
                 "~exit 1"}),
         false, "t.cpp:3: ERROR: CHECK( a ) is NOT correct!"},
        {"doctest's counters zeroed, the harness's count not",
         run(0, {"~start\n" + kName, "~end 4 2 0 0 1\nx: ERROR: y", "~run 1 0 4 0", "~exit 0"}), false, "x: ERROR: y"},
        {"the harness's count zero, doctest's not",
         run(0, {"~start\n" + kName, "~end 4 0 3 0 1", "~run 1 0 4 0", "~exit 0"}), false,
         "doctest counted failed assertions"},
        {"a failure whose text begins with an empty line (fuzz/corpus/grade)",
         run(1, {"~start\n" + kName, "~end 3 1 1 1 0\n\nsecond line", "~run 1 1 3 1", "~exit 1"}), false,
         "failed (doctest's failure flags 1)"},
        {"an exception",
         run(1, {"~start\n" + kName, "~exception 0\nbad input", "~end 0 0 0 2 0", "~run 1 1 0 0", "~exit 1"}), false,
         "threw: bad input"},
        {"the records of a pass, forged with a guessed token",
         run(0, {std::string(32, '0') + " start\n" + kName, std::string(32, '0') + " end 1 0 0 0 1",
                 std::string(32, '0') + " run 1 0 1 0", std::string(32, '0') + " exit 0"}),
         false, "4 message(s) on the grader's result channel that the test harness did not send"},
        {"a pass and one forged message",
         run(0,
             [] {
                 auto r = kPass;
                 r.push_back("exit 0");
                 return r;
             }()),
         false, "1 message(s)"},
        {"a record with a malformed number", run(0, badNumber), false, "1 message(s)"},
        {"another test case than the one asked for", run(0, renamed), false, "ran 'rays: another test [1 pt]'"},
        {"two test cases", run(0, twice), false, "selected 2 test cases"},
        {"records out of order", run(0, reordered), false, "out of order"},
        {"a name that selects nothing", run(0, {"~run 0 0 0 0", "~exit 0"}), false, "selected no test case"},
        {"a pass, then exit status 3", run(3, kPass), false, "the program ended with exit status 3"},
        {"a pass, then a crash", crashed, false, "crashed: killed by signal 11"},
        {"bwrap's status of a crash", run(139, kPass), false, "crashed: killed by signal 11"},
        {"the time limit", timedOut, false, "timed out after 5 s"},
        {"a flooded channel", overflow, false, "more to the grader's result channel than a test can"},
    };
    int wrong = 0;
    for (const Case& c : cases) {
        const grade::Verdict v = grade::judge(c.o, kName, 5, true);
        const bool ok = v.passed == c.passes && v.message.find(c.says) != std::string::npos;
        std::printf("%s %s: %s\n", ok ? "ok  " : "FAIL", c.what, v.passed ? "passed" : v.message.c_str());
        if (!ok) std::printf("     expected %s%s\n", c.passes ? "a pass" : "a fail saying: ", c.says.c_str()), ++wrong;
    }
    std::printf("%d of %zu verdicts as expected\n", int(cases.size()) - wrong, cases.size());
    return wrong ? 1 : 0;
}
