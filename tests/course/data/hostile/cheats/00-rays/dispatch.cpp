// Hostile: the skeleton (hooked: ../../attack.h) attacking the verdict a different way in each of
// six tests, chosen by the test's name on the command line. Graded twice by hostile.sh: with the
// object check, which refuses every file here by name; and with --no-object-check, where each
// attack runs and the result channel alone must give every test 0.
#include <fstream>
#include <iterator>
#include <string>

#include "attack.h"

void attackFakeSummary();  // fake_summary.cpp
void attackAbort();        // abort.cpp
void attackSyscall();      // syscall.cpp
void attackFdWrite();      // fd_write.cpp
void attackCounters();     // counters.cpp

// The test this process runs: doctest's --test-case=NAME on the command line.
std::string hostileTestName() {
    std::ifstream in("/proc/self/cmdline");
    const std::string cmdline((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t at = cmdline.find("--test-case=");
    return at == std::string::npos ? "" : cmdline.substr(at + 12, cmdline.find('\0', at) - at - 12);
}

void hostileAttack() {
    const std::string t = hostileTestName();
    if (t.find("through the image centre") != std::string::npos) attackFakeSummary();
    else if (t.find("corners of the image") != std::string::npos) attackAbort();
    else if (t.find("midpoints of the image edges") != std::string::npos) attackSyscall();
    else if (t.find("non-square images") != std::string::npos) attackFdWrite();
    else if (t.find("round to 0 in float") != std::string::npos) attackCounters();
    // "generateRay and Camera::rasterPosition are inverse": constructor.cpp, before main()
}
