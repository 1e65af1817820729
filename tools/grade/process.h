// One step of grading (a build, one test) as a process the grader controls to the end: a time
// limit, resource limits, and when the step ends every process it started is gone.
//
// Each step runs under a supervisor, a process forked by the grader for that step alone. The
// supervisor is a "child subreaper" (prctl PR_SET_CHILD_SUBREAPER): whatever the step starts,
// even a daemon that forks twice and calls setsid(), stays its descendant. When the step's
// command exits, or its time is up, the supervisor SIGKILLs the command's process group and then
// every child it still has, again and again, until it has none; only then does it report back.
// So when run() returns, no process of that step is left (in the sandbox, the pid namespace
// dies with bwrap as well: tools/grade/sandbox.h).
#pragma once
#include <string>
#include <vector>

namespace grade {

struct Step {
    std::vector<std::string> argv;  // argv[0]: the program, an absolute path
    std::vector<std::string> env;   // the whole environment ("NAME=value")
    std::string cwd;                // working directory
    std::string log;                // stdout and stderr go to this file (made by the grader)
    double timeout = 0;             // seconds; 0: none
    bool unprivileged = false;      // when the grader runs as root: run as nobody (uid, gid 65534)
    bool limits = false;            // resource limits for submission code (see process.cpp)
};

struct Outcome {
    bool timedOut = false;
    int exitCode = -1;  // when the command exited
    int signal = 0;     // when a signal (not the time limit) ended it
    double seconds = 0;
    std::string error;  // the step could not be run at all
    bool ok() const { return error.empty() && !timedOut && signal == 0 && exitCode == 0; }
    // "exit status 2", "killed by signal 11 (Segmentation fault)", "timed out after 5 s"
    std::string describe(double timeout) const;
};

// Runs the steps, at most `jobs` at a time; the outcomes in the order of the steps.
std::vector<Outcome> runAll(const std::vector<Step>& steps, int jobs);
inline Outcome run(const Step& step) { return runAll({step}, 1).front(); }

// The uid and gid of "nobody", the identity submission code runs as when the grader is root.
constexpr int kNobody = 65534;

}  // namespace grade
