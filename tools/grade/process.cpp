// Steps under supervisors (process.h). Linux only: prctl, /proc, pipes and socket pairs.
#include "process.h"

#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/random.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <dirent.h>
#include <map>
#include <sstream>
#include <thread>

#include "grade_channel.h"

namespace grade {

namespace {

// Limits for submission code (Step::limits): no core files, no file above Step::fileSizeLimit
// (an object or a scratch file that grows without end; the log is the supervisor's and capped
// apart), 4 GiB of address space per process, 1024 processes for the sandbox's user (a fork
// bomb; not enforced for root, who is never the one running submissions when the grader is root).
void setLimits(const Step& step) {
    auto set = [](int what, rlim_t value) {
        const rlimit r{value, value};
        setrlimit(what, &r);
    };
    set(RLIMIT_CORE, 0);
    set(RLIMIT_FSIZE, rlim_t(step.fileSizeLimit));
    set(RLIMIT_AS, rlim_t(4) << 30);
    set(RLIMIT_NPROC, 1024);
}

// In the command's process, before exec: never returns. `out` is the write end of the output
// pipe, `channel` the harness's end of the result channel (or -1).
[[noreturn]] void execCommand(const Step& step, int out, int channel) {
    setpgid(0, 0);
    // Above every number dup2 writes to first, so that none is overwritten before it is moved.
    out = fcntl(out, F_DUPFD_CLOEXEC, 10);
    if (channel >= 0) channel = fcntl(channel, F_DUPFD_CLOEXEC, 10);
    const int devNull = open("/dev/null", O_RDONLY | O_CLOEXEC);
    if (out < 0 || devNull < 0 || (step.channel && channel < 0)) _exit(127);
    dup2(devNull, 0);
    dup2(out, 1);
    dup2(out, 2);
    if (channel >= 0) dup2(channel, ps::gradechannel::kFd);
    close_range(channel >= 0 ? ps::gradechannel::kFd + 1 : 3, ~0U, 0);  // nothing else of the grader's
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
    if (step.limits) setLimits(step);
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

// The log of one step as it keeps the command's output: the first `head_` bytes written as they
// come, the last `tailCap_` bytes held in memory and written at the end, after a line that says
// how many bytes between them were left out.
class Capture {
public:
    Capture(int fd, std::uint64_t cap, bool keepTail) : fd_(fd) {
        if (cap == 0) head_ = UINT64_MAX;
        else if (keepTail) head_ = cap / 4, tailCap_ = cap - head_;
        else head_ = cap;
    }
    void add(const char* p, size_t n) {
        total_ += n;
        if (written_ < head_) {
            const size_t k = size_t(std::min<std::uint64_t>(n, head_ - written_));
            put(p, k);
            written_ += k;
            p += k, n -= k;
        }
        if (n == 0 || tailCap_ == 0) return;
        tail_.append(p, n);
        if (tail_.size() > 2 * tailCap_) tail_.erase(0, tail_.size() - tailCap_);
    }
    void finish() {
        if (tail_.size() > tailCap_) tail_.erase(0, tail_.size() - tailCap_);
        const std::uint64_t left = total_ - written_ - tail_.size();
        if (left > 0) {
            const std::string note = "\n[grade: " + std::to_string(left) +
                                     " bytes of output left out here; a log keeps the first " + std::to_string(head_) +
                                     " and the last " + std::to_string(tailCap_) + "]\n";
            put(note.data(), note.size());
        }
        put(tail_.data(), tail_.size());
    }
    std::uint64_t total() const { return total_; }
    const std::string& error() const { return error_; }

private:
    void put(const char* p, size_t n) {
        while (n > 0 && error_.empty()) {
            const ssize_t w = write(fd_, p, n);
            if (w < 0 && errno == EINTR) continue;
            if (w <= 0) error_ = std::strerror(w < 0 ? errno : ENOSPC);
            else p += w, n -= size_t(w);
        }
    }
    int fd_;
    std::uint64_t head_ = 0, tailCap_ = 0, written_ = 0, total_ = 0;
    std::string tail_, error_;
};

// Reads what the pipe holds now (at most `most` bytes, so that a command printing without end
// cannot keep the supervisor from its clock); true at the end of the stream.
bool drain(int fd, Capture& capture, size_t most) {
    static char buf[1 << 16];
    for (size_t got = 0; got < most;) {
        const ssize_t n = read(fd, buf, sizeof buf);
        if (n > 0) {
            capture.add(buf, size_t(n));
            got += size_t(n);
        } else if (n == 0) return true;
        else if (errno != EINTR) return errno != EAGAIN;
    }
    return false;
}

// The supervisor of one step (see process.h); writes the outcome to `report` and exits.
[[noreturn]] void supervise(const Step& step, int report, int channel) {
    prctl(PR_SET_PDEATHSIG, SIGKILL);  // dies with the grader (and then so does the command)
    prctl(PR_SET_CHILD_SUBREAPER, 1);  // orphans of the step become its children
    Outcome out;
    const int logFd = open(step.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    int pipeFds[2] = {-1, -1};
    const auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    const bool ready = logFd >= 0 && pipe2(pipeFds, O_CLOEXEC) == 0;
    const pid_t child = ready ? fork() : -1;
    if (child == 0) execCommand(step, pipeFds[1], channel);
    if (child < 0) {
        out.error = "cannot start " + step.argv[0] + " (log " + step.log + "): " + std::strerror(errno);
    } else {
        setpgid(child, child);  // also here: no race with the kill below
        close(pipeFds[1]);
        if (channel >= 0) close(channel);
        const int output = pipeFds[0];
        fcntl(output, F_SETFL, O_NONBLOCK);
        fcntl(output, F_SETPIPE_SZ, 1 << 20);  // fewer wake-ups for a command that prints a lot
        Capture capture(logFd, step.logCap, step.logTail);
        bool ended = false;  // the output's end: every writer has closed it
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
            if (ended) {
                std::this_thread::sleep_for(std::chrono::milliseconds(pause));
                continue;
            }
            pollfd p{output, POLLIN, 0};
            if (poll(&p, 1, pause) > 0) {
                const std::uint64_t before = capture.total();
                ended = drain(output, capture, 16 << 20);
                if (capture.total() > before) pause = 1;
            }
        }
        out.seconds = elapsed();
        if (!out.timedOut) {
            if (info.si_code == CLD_EXITED) out.exitCode = info.si_status;
            else out.signal = info.si_status;
        }
        // Everything the step left behind: its process group, then every child this supervisor
        // has (the command, the orphans it inherited), until there is none.
        kill(-child, SIGKILL);
        reapEveryChild();
        // What is still in the pipe: its writers are gone, so this ends (bounded all the same).
        if (!ended) drain(output, capture, size_t(64) << 20);
        capture.finish();
        out.outputBytes = capture.total();
        out.logError = capture.error().empty() ? "" : "cannot write " + step.log + ": " + capture.error();
        close(output);
    }
    if (logFd >= 0 && close(logFd) != 0 && out.logError.empty())
        out.logError = "cannot write " + step.log + ": " + std::strerror(errno);
    std::ostringstream s;
    s << out.timedOut << ' ' << out.exitCode << ' ' << out.signal << ' ' << out.seconds << ' ' << out.outputBytes
      << '\n'
      << out.logError << '\0' << out.error;
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
    if (!(in >> out.timedOut >> out.exitCode >> out.signal >> out.seconds >> out.outputBytes)) {
        out.error = "the grader's supervisor of this step died (" +
                    (WIFSIGNALED(supervisorStatus) ? "signal " + std::to_string(WTERMSIG(supervisorStatus))
                                                   : "exit status " + std::to_string(WEXITSTATUS(supervisorStatus))) +
                    ", report '" + text + "')";
        return out;
    }
    in.get();
    std::getline(in, out.logError, '\0');
    std::getline(in, out.error, '\0');
    return out;
}

// A fresh token for a channel: kTokenBytes random bytes (the kernel's generator).
std::string randomToken() {
    std::string token(ps::gradechannel::kTokenBytes, '\0');
    size_t got = 0;
    while (got < token.size()) {
        const ssize_t n = getrandom(&token[got], token.size() - got, 0);
        if (n > 0) got += size_t(n);
        else if (errno != EINTR) throw std::runtime_error(std::string("getrandom: ") + std::strerror(errno));
    }
    return token;
}

std::string hex(const std::string& bytes) {
    static const char digits[] = "0123456789abcdef";
    std::string h;
    for (unsigned char c : bytes) h += digits[c >> 4], h += digits[c & 15];
    return h;
}

// Every record the channel holds (the step's processes are gone, so nothing more comes).
void readChannel(int fd, Outcome& out) {
    std::vector<char> buf(ps::gradechannel::kMaxRecord + 1);
    size_t bytes = 0;
    for (;;) {
        const ssize_t n = recv(fd, buf.data(), buf.size(), MSG_DONTWAIT | MSG_TRUNC);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        bytes += size_t(n);
        if (out.channel.size() == kMaxChannelRecords || bytes > kMaxChannelBytes) {
            out.channelOverflow = true;
            break;
        }
        out.channel.emplace_back(buf.data(), std::min(size_t(n), buf.size()));
    }
    close(fd);
}

struct Running {
    size_t step;
    int report;   // the supervisor's report pipe
    int channel;  // the grader's end of the step's channel, or -1
    std::string token;
};

}  // namespace

void reapEveryChild() {
    for (;;) {
        for (pid_t p : myChildren()) kill(p, SIGKILL);
        if (waitpid(-1, nullptr, 0) < 0 && errno == ECHILD) break;
    }
}

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
    std::map<pid_t, Running> running;  // supervisor -> its step
    size_t next = 0;
    std::fflush(nullptr);  // nothing buffered twice by the forks
    while (next < steps.size() || !running.empty()) {
        while (next < steps.size() && int(running.size()) < std::max(jobs, 1)) {
            const Step& step = steps[next];
            int fds[2], chan[2] = {-1, -1};
            std::string token;
            if (pipe2(fds, O_CLOEXEC) != 0) {
                outcomes[next++].error = std::string("pipe: ") + std::strerror(errno);
                continue;
            }
            if (step.channel) {
                token = randomToken();
                if (socketpair(AF_UNIX, SOCK_SEQPACKET | SOCK_CLOEXEC, 0, chan) != 0 ||
                    send(chan[0], token.data(), token.size(), MSG_NOSIGNAL) != ssize_t(token.size())) {
                    outcomes[next++].error = std::string("the result channel: ") + std::strerror(errno);
                    for (int fd : {fds[0], fds[1], chan[0], chan[1]})
                        if (fd >= 0) close(fd);
                    continue;
                }
            }
            const pid_t sup = fork();
            if (sup == 0) {
                close(fds[0]);
                if (chan[0] >= 0) close(chan[0]);
                supervise(step, fds[1], chan[1]);
            }
            close(fds[1]);
            if (chan[1] >= 0) close(chan[1]);
            if (sup < 0) {
                close(fds[0]);
                if (chan[0] >= 0) close(chan[0]);
                outcomes[next++].error = std::string("fork: ") + std::strerror(errno);
                continue;
            }
            running[sup] = {next++, fds[0], chan[0], hex(token)};
        }
        if (running.empty()) break;
        int status = 0;
        const pid_t done = waitpid(-1, &status, 0);
        auto it = running.find(done);
        if (it == running.end()) continue;
        Outcome& out = outcomes[it->second.step];
        out = readOutcome(it->second.report, status);
        if (it->second.channel >= 0) {
            out.token = it->second.token;
            readChannel(it->second.channel, out);
        }
        running.erase(it);
    }
    return outcomes;
}

}  // namespace grade
