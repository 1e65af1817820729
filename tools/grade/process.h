// One step of grading (a build, one test) as a process the grader controls to the end: a time
// limit, resource limits, a cap on what its log keeps, and when the step ends every process it
// started is gone.
//
// Each step runs under a supervisor, a process forked by the grader for that step alone. The
// supervisor is a "child subreaper" (prctl PR_SET_CHILD_SUBREAPER): whatever the step starts,
// even a daemon that forks twice and calls setsid(), stays its descendant. The command's stdout
// and stderr are a pipe the supervisor reads: the log file gets at most Step::logCap bytes of it
// (the start and the end, with a line saying how much was left out between them), however much
// the command prints. When the command exits, or its time is up, the supervisor SIGKILLs the
// command's process group and then every child it still has, again and again, until it has
// none; only then does it report back. So when run() returns, no process of that step is left
// (in the sandbox, the pid namespace dies with bwrap as well: tools/grade/sandbox.h).
//
// A step with a channel (Step::channel) gets the grader's result channel as file descriptor 3
// (tests/support/grade_channel.h): a fresh socket pair and token per step; the records the
// harness sent on it are the outcome's `channel`, read once the step's processes are gone.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace grade {

struct Step {
    std::vector<std::string> argv;  // argv[0]: the program, an absolute path
    std::vector<std::string> env;   // the whole environment ("NAME=value")
    std::string cwd;                // working directory
    std::string log;                // stdout and stderr go to this file (made by the supervisor)
    std::uint64_t logCap = 0;       // at most this many bytes of output in the log (0: no cap)
    bool logTail = true;            // over the cap: keep the start and the end (false: the start)
    double timeout = 0;             // seconds; 0: none
    bool unprivileged = false;      // when the grader runs as root: run as nobody (uid, gid 65534)
    bool limits = false;            // resource limits for submission code (see process.cpp)
    std::uint64_t fileSizeLimit = std::uint64_t(64) << 20;  // with limits: no file larger (RLIMIT_FSIZE)
    bool channel = false;                                   // the grader's result channel as fd 3 (grade_channel.h)
};

struct Outcome {
    bool timedOut = false;
    int exitCode = -1;  // when the command exited
    int signal = 0;     // when a signal (not the time limit) ended it
    double seconds = 0;
    std::string error;                 // the step could not be run at all
    std::uint64_t outputBytes = 0;     // all the command printed (the log keeps at most Step::logCap)
    std::string logError;              // the log could not be written (the grader's problem, not the step's)
    std::string token;                 // with a channel: the token the harness was given, in hex
    std::vector<std::string> channel;  // with a channel: the records, in the order they were sent
    bool channelOverflow = false;      // more records (or bytes) than a test can honestly send
    bool ok() const { return error.empty() && !timedOut && signal == 0 && exitCode == 0; }
    // "exit status 2", "killed by signal 11 (Segmentation fault)", "timed out after 5 s"
    std::string describe(double timeout) const;
};

// Runs the steps, at most `jobs` at a time; the outcomes in the order of the steps.
std::vector<Outcome> runAll(const std::vector<Step>& steps, int jobs);
inline Outcome run(const Step& step) { return runAll({step}, 1).front(); }

// SIGKILLs every child of this process and waits for it, again and again until there is none
// (a child subreaper's orphans included).
void reapEveryChild();

// The uid and gid of "nobody", the identity submission code runs as when the grader is root.
constexpr int kNobody = 65534;

// The most a channel may hold: a test case sends five records of at most 8 KiB.
constexpr std::size_t kMaxChannelRecords = 64;
constexpr std::size_t kMaxChannelBytes = 256 << 10;

}  // namespace grade
