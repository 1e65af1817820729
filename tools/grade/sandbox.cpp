// bwrap command lines (sandbox.h).
#include "sandbox.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace grade {

std::string findProgram(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::istringstream dirs(std::string(path ? path : "") + ":/usr/bin:/bin");
    for (std::string d; std::getline(dirs, d, ':');) {
        if (d.empty()) continue;
        const fs::path p = fs::path(d) / name;
        if (access(p.c_str(), X_OK) == 0 && fs::is_regular_file(p)) return p.string();
    }
    return "";
}

Step Sandbox::wrap(Step step, const View& view) const {
    if (!on()) return step;
    std::vector<std::string> a = {
        bwrap_, "--unshare-all", "--unshare-user", "--disable-userns", "--die-with-parent", "--new-session"};
    // The system, read-only. /bin, /lib, ... are links into /usr on Debian 12 ("merged /usr").
    a.insert(a.end(), {"--ro-bind", "/usr", "/usr"});
    for (const char* top : {"/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"}) {
        std::error_code ec;
        if (fs::is_symlink(top, ec)) a.insert(a.end(), {"--symlink", fs::read_symlink(top, ec).string(), top});
        else if (fs::is_directory(top, ec)) a.insert(a.end(), {"--ro-bind", top, top});
    }
    a.insert(a.end(), {"--ro-bind-try", "/etc/ld.so.cache", "/etc/ld.so.cache", "--ro-bind-try", "/etc/alternatives",
                       "/etc/alternatives", "--proc", "/proc", "--dev", "/dev", "--size", std::to_string(256 << 20),
                       "--tmpfs", "/tmp"});
    for (const std::string& p : view.readOnly) a.insert(a.end(), {"--ro-bind", p, p});
    for (const std::string& p : view.writable) a.insert(a.end(), {"--bind", p, p});
    for (const std::string& p : view.scratch)
        a.insert(a.end(), {"--size", std::to_string(view.scratchBytes), "--tmpfs", p});
    // The root holds the mount points bwrap made for the view: read-only like the rest. So does
    // the empty /tmp once the view is in place: a view under /tmp (a tree or a build there) has
    // its parent folders made in it, where a submission could otherwise write at the paths of the
    // source tree or OUT (only in the sandbox's memory, but a probe cannot tell). Steps write
    // their temporary files to TMPDIR, their own folder (lesson.cpp).
    a.insert(a.end(), {"--remount-ro", "/", "--remount-ro", "/tmp"});
    if (!step.cwd.empty()) a.insert(a.end(), {"--chdir", step.cwd});
    a.push_back("--");
    a.insert(a.end(), step.argv.begin(), step.argv.end());
    step.argv = a;
    step.unprivileged = unprivileged_;
    return step;
}

Sandbox Sandbox::probe(const View& view, std::string& why) {
    Sandbox box;
    const char* chosen = std::getenv("PATHSPACE_GRADE_BWRAP");  // the operator's choice (and the tests')
    box.bwrap_ = chosen && *chosen ? std::string(chosen) : findProgram("bwrap");
    if (box.bwrap_.empty()) {
        why = "bwrap (Debian package bubblewrap) is not installed";
        return Sandbox();
    }
    // A step that reads every path of the view: as nobody first when root.
    const fs::path log = fs::temp_directory_path() / ("grade-probe-" + std::to_string(getpid()) + ".log");
    Step check;
    check.argv = {"/bin/sh", "-c", "for p in \"$@\"; do test -r \"$p\" || { echo \"cannot read $p\"; exit 1; }; done",
                  "probe"};
    check.argv.insert(check.argv.end(), view.readOnly.begin(), view.readOnly.end());
    check.env = {"PATH=/usr/bin:/bin"};
    check.cwd = "/";
    check.log = log.string();
    check.timeout = 30;
    std::string tried;
    for (bool unprivileged : {true, false}) {
        if (unprivileged && geteuid() != 0) continue;
        box.unprivileged_ = unprivileged;
        const Outcome o = run(box.wrap(check, view));
        std::ifstream in(log);
        std::string said((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (o.ok()) {
            fs::remove(log);
            return box;
        }
        tried += std::string(tried.empty() ? "" : "; ") + (unprivileged ? "as nobody: " : "as this user: ") +
                 o.describe(check.timeout) + (said.empty() ? "" : ", " + said.substr(0, said.find('\n')));
    }
    fs::remove(log);
    why = box.bwrap_ + " does not work here (" + tried + ")";
    return Sandbox();
}

}  // namespace grade
