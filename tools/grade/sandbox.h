// The sandbox submission code runs in (README, "The autograder"): Debian's bubblewrap (bwrap)
// with new user, pid, network, IPC, UTS and cgroup namespaces, so: no network, no other process
// visible, and a filesystem that holds only
//   - the system, read-only: /usr (and /bin, /lib, ... as the host has them), ld.so.cache and the
//     compiler alternatives of /etc; a private /proc, a minimal /dev and an empty /tmp;
//   - the paths of the step's View, read-only or writable, at the same place as outside (so a
//     step's command is the same with and without the sandbox); a scratch path of the view is an
//     empty memory file system of View::scratchBytes instead (a test writes nothing to the host).
// Nothing else: not the source tree, not the solutions, not OUT, not other submissions, not
// $HOME. When the grader is root, submission code runs as nobody (uid 65534) as well, so even a
// path the view got wrong would not be writable. bwrap's pid 1 takes every process of the
// sandbox with it when it ends (--unshare-pid, --die-with-parent).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "process.h"

namespace grade {

struct View {
    std::vector<std::string> readOnly;                     // host paths shown read-only
    std::vector<std::string> writable;                     // host paths shown writable
    std::vector<std::string> scratch;                      // paths that are an empty writable tmpfs in the sandbox
    std::uint64_t scratchBytes = std::uint64_t(64) << 20;  // the size of each
};

class Sandbox {
public:
    // Off: runs steps as they are (grade --no-sandbox).
    Sandbox() = default;
    // Finds bwrap and checks that it works with `view`, first as nobody (when root), else as the
    // grader's user; on failure `why` says what is wrong and the sandbox is off.
    static Sandbox probe(const View& view, std::string& why);

    bool on() const { return !bwrap_.empty(); }
    bool unprivileged() const { return unprivileged_; }
    // The step run inside the sandbox showing `view` (unchanged when off).
    Step wrap(Step step, const View& view) const;

private:
    std::string bwrap_;
    bool unprivileged_ = false;
};

// The first executable NAME on PATH (or the usual system folders), "" if none.
std::string findProgram(const std::string& name);

}  // namespace grade
