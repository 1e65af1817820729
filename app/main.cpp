// pathspace: the command-line front end. The commands register themselves (app/command.h,
// one file each in app/commands/); this file only finds the one asked for and turns errors into
// messages and exit statuses. `pathspace --help` lists the commands.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>
#include "command.h"
#include "errors.h"
#include "passive_wait.h"
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace {

int runCommandLine(std::vector<std::string> args) {
    try {
        if (args.empty() || args[0] == "--help" || args[0] == "-h") {
            std::cout << ps::programHelp();
            return args.empty() ? 2 : 0;
        }
        const ps::Command* command = ps::findCommand(args[0]);
        if (!command) throw ps::UsageError("unknown command '" + args[0] + "'");
        args.erase(args.begin());
        for (const auto& a : args)
            if (a == "--help" || a == "-h") {
                std::cout << ps::commandHelp(*command);
                return 0;
            }
        return command->run(args);
    } catch (const ps::UsageError& e) {
        // A message of several lines (an expression and a caret under its fault) keeps them
        // together and says the rest on a line of its own.
        const std::string what = e.what();
        std::cerr << "pathspace: " << what << (what.find('\n') == std::string::npos ? " " : "\n")
                  << "(run 'pathspace --help' for usage)\n";
        return 2;
    } catch (const ps::InputError& e) {
        std::cerr << "pathspace: error: " << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "pathspace: internal error: " << e.what() << "\n";
        return 3;
    }
}

// Standard output is a file too when it is redirected (pathspace compare A B > result.txt): what
// was not written to it, up to its last flush, is an error as for every other file (a full disk
// is never silent), never an exit status of 0.
int finishStandardOutput(int status) {
    errno = 0;
    std::cout.flush();
    const bool failed = std::fflush(stdout) != 0 || std::ferror(stdout) != 0 || !std::cout;
    if (!failed) return status;
    const int err = errno;
    std::cerr << "pathspace: error: standard output: write failed ("
              << (err != 0 ? std::strerror(err) : "an earlier write failed") << ")\n";
    return status == 0 ? 1 : status;
}

// glibc gives a large freed block back to the kernel (a block above its mmap threshold at once,
// the heap's top once more than the trim threshold is free there), and the next allocation of that
// size pays for the kernel's zeroed pages again. A render that allocates and frees tens of MB per
// iteration (ppm's photon map and kd-tree: about 50 MB a pass on SmallVCM's scenes) spent about
// 5 % of its CPU time in those page faults (bench/README.md, "ppm against SmallVCM's ppm"): keep
// freed memory for reuse instead (the highest mmap threshold glibc accepts, 32 MB; no trimming
// below 1 GB). Elsewhere: nothing.
void keepFreedMemory() {
#if defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
}

}  // namespace

int main(int argc, char** argv) {
    ps::preferPassiveWaiting(argv);
    keepFreedMemory();
    return finishStandardOutput(runCommandLine(std::vector<std::string>(argv + 1, argv + argc)));
}
