// Hostile: next to the reference rays.cpp, code that runs when the test program starts and, by
// the test it is asked to run (doctest's --test-case=... on the command line), hangs, crashes or
// ends the program with status 0 before doctest can report a failure. Each of those tests must
// score 0 (timed out, crashed, no doctest summary); every other test must pass.
#include <signal.h>
#include <unistd.h>

#include <fstream>
#include <iterator>
#include <string>

namespace {

const bool misbehaved = [] {
    std::ifstream in("/proc/self/cmdline");
    const std::string cmdline((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (cmdline.find("centre of a triangle fan") != std::string::npos)
        for (;;) pause();                                                                  // hang
    if (cmdline.find("triangles behind the origin") != std::string::npos) raise(SIGSEGV);  // crash
    if (cmdline.find("strictly inside the open segment") != std::string::npos) _exit(0);   // a fake pass
    return true;
}();

}  // namespace
