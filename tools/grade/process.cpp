// Steps under supervisors (process.h). Linux only: prctl, /proc.
#include "process.h"

#include <fcntl.h>
#include <grp.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <dirent.h>
#include <map>
#include <sstream>
#include <thread>

namespace grade {

namespace {

// Limits for submission code (Step::limits): no core files, no file above 256 MiB (a log or an
// object that grows without end), 4 GiB of address space per process, 1024 processes for the
// sandbox's user (a fork bomb; not enforced for root, who is never the one running submissions
// when the grader is root).
void setLimits() {
    auto set = [](int what, rlim_t value) {
        const rlimit r{value, value};
        setrlimit(what, &r);
    };
    set(RLIMIT_CORE, 0);
    set(RLIMIT_FSIZE, rlim_t(256) << 20);
    set(RLIMIT_AS, rlim_t(4) << 30);
    set(RLIMIT_NPROC, 1024);
}

// In the command's process, before exec: never returns.
[[noreturn]] void execCommand(const Step& step, int logFd) {
    setpgid(0, 0);
    const int devNull = open("/dev/null", O_RDONLY);
    dup2(devNull, 0);
    dup2(logFd, 1);
    dup2(logFd, 2);
    close_range(3, ~0U, 0);  // nothing of the grader's reaches the command
    if (!step.cwd.empty() && chdir(step.cwd.c_str()) != 0) {
        dprintf(2, "grade: cannot enter %s: %s\n", step.cwd.c_str(), std::strerror(errno));
        _exit(127);
    }
    if (step.unprivileged && geteuid() == 0) {
        if (setgroups(0, nullptr) != 0 || setgid(kNobody) != 0 || setuid(kNobody) != 0) {
            dprintf(2, "grade: cannot become uid %d: %s\n", kNobody, std::strerror(errno));
            _exit(127);
        }
    }
    if (step.limits) setLimits();
    prctl(PR_SET_PDEATHSIG, SIGKILL);  // after setuid, which clears it: dies with its supervisor
    std::vector<char*> argv, env;
    for (const std::string& a : step.argv) argv.push_back(const_cast<char*>(a.c_str()));
    for (const std::string& e : step.env) env.push_back(const_cast<char*>(e.c_str()));
    argv.push_back(nullptr);
    env.push_back(nullptr);
    execve(argv[0], argv.data(), env.data());
    dprintf(2, "grade: cannot run %s: %s\n", argv[0], std::strerror(errno));
    _exit(127);
}

// The processes whose parent is this one, from /proc/PID/stat ("pid (comm) state ppid ...";
// comm may hold spaces and parentheses, so the fields are read after the last ')').
std::vector<pid_t> myChildren() {
    std::vector<pid_t> kids;
    const pid_t me = getpid();
    DIR* proc = opendir("/proc");
    if (!proc) return kids;
    while (dirent* e = readdir(proc)) {
        char* end = nullptr;
        const long pid = std::strtol(e->d_name, &end, 10);
        if (*end != '\0' || pid <= 0) continue;
        // read(), not a stream: a process may end while it is read (ESRCH), which libstdc++'s
        // streambuf iterators turn into an exception.
        char buf[1024];
        const int fd = open((std::string("/proc/") + e->d_name + "/stat").c_str(), O_RDONLY | O_CLOEXEC);
        if (fd < 0) continue;
        const ssize_t n = read(fd, buf, sizeof buf);
        close(fd);
        if (n <= 0) continue;
        const std::string stat(buf, size_t(n));
        const size_t paren = stat.rfind(')');
        if (paren == std::string::npos) continue;
        std::istringstream fields(stat.substr(paren + 1));
        std::string state;
        long ppid = 0;
        if (fields >> state >> ppid && ppid == me) kids.push_back(static_cast<pid_t>(pid));
    }
    closedir(proc);
    return kids;
}

// The supervisor of one step (see process.h); writes the outcome to `report` and exits.
[[noreturn]] void supervise(const Step& step, int report) {
    prctl(PR_SET_PDEATHSIG, SIGKILL);  // dies with the grader (and then so does the command)
    prctl(PR_SET_CHILD_SUBREAPER, 1);  // orphans of the step become its children
    Outcome out;
    const int logFd = open(step.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    const auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    const pid_t child = logFd < 0 ? -1 : fork();
    if (child == 0) execCommand(step, logFd);
    if (child < 0) {
        out.error = "cannot start " + step.argv[0] + " (log " + step.log + "): " + std::strerror(errno);
    } else {
        setpgid(child, child);  // also here: no race with the kill below
        // Wait for the command to end, without reaping it (WNOWAIT): while it is a zombie, its
        // pid, which names its process group, cannot be given to another process.
        siginfo_t info{};
        for (int pause = 1;; pause = std::min(pause * 2, 20)) {
            info.si_pid = 0;
            if (waitid(P_PID, child, &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == child) break;
            if (step.timeout > 0 && elapsed() > step.timeout) {
                out.timedOut = true;
                kill(-child, SIGKILL);
                kill(child, SIGKILL);
                waitid(P_PID, child, &info, WEXITED | WNOWAIT);
                break;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(pause));
        }
        out.seconds = elapsed();
        if (!out.timedOut) {
            if (info.si_code == CLD_EXITED) out.exitCode = info.si_status;
            else out.signal = info.si_status;
        }
        // Everything the step left behind: its process group, then every child this supervisor
        // has (the command, the orphans it inherited), until there is none.
        kill(-child, SIGKILL);
        for (;;) {
            for (pid_t p : myChildren()) kill(p, SIGKILL);
            if (waitpid(-1, nullptr, 0) < 0 && errno == ECHILD) break;
        }
    }
    std::ostringstream s;
    s << out.timedOut << ' ' << out.exitCode << ' ' << out.signal << ' ' << out.seconds << '\n' << out.error;
    const std::string text = s.str();
    ssize_t written = write(report, text.data(), text.size());
    (void)written;
    _exit(0);
}

Outcome readOutcome(int fd, int supervisorStatus) {
    std::string text;
    char buf[4096];
    for (ssize_t n; (n = read(fd, buf, sizeof buf)) > 0;) text.append(buf, size_t(n));
    close(fd);
    Outcome out;
    std::istringstream in(text);
    if (!(in >> out.timedOut >> out.exitCode >> out.signal >> out.seconds)) {
        out.error = "the grader's supervisor of this step died (" +
                    (WIFSIGNALED(supervisorStatus) ? "signal " + std::to_string(WTERMSIG(supervisorStatus))
                                                   : "exit status " + std::to_string(WEXITSTATUS(supervisorStatus))) +
                    ", report '" + text + "')";
        return out;
    }
    in.get();
    std::getline(in, out.error, '\0');
    return out;
}

}  // namespace

std::string Outcome::describe(double timeout) const {
    if (!error.empty()) return error;
    if (timedOut) {
        std::ostringstream s;
        s << "timed out after " << timeout << " s";
        return s.str();
    }
    if (signal) return "killed by signal " + std::to_string(signal) + " (" + strsignal(signal) + ")";
    return "exit status " + std::to_string(exitCode);
}

std::vector<Outcome> runAll(const std::vector<Step>& steps, int jobs) {
    std::vector<Outcome> outcomes(steps.size());
    std::map<pid_t, std::pair<size_t, int>> running;  // supervisor -> (step, its report pipe)
    size_t next = 0;
    std::fflush(nullptr);  // nothing buffered twice by the forks
    while (next < steps.size() || !running.empty()) {
        while (next < steps.size() && int(running.size()) < std::max(jobs, 1)) {
            int fds[2];
            if (pipe2(fds, O_CLOEXEC) != 0) {
                outcomes[next++].error = std::string("pipe: ") + std::strerror(errno);
                continue;
            }
            const pid_t sup = fork();
            if (sup == 0) {
                close(fds[0]);
                supervise(steps[next], fds[1]);
            }
            close(fds[1]);
            if (sup < 0) {
                close(fds[0]);
                outcomes[next++].error = std::string("fork: ") + std::strerror(errno);
                continue;
            }
            running[sup] = {next++, fds[0]};
        }
        if (running.empty()) break;
        int status = 0;
        const pid_t done = waitpid(-1, &status, 0);
        auto it = running.find(done);
        if (it == running.end()) continue;
        outcomes[it->second.first] = readOutcome(it->second.second, status);
        running.erase(it);
    }
    return outcomes;
}

}  // namespace grade
