// Hostile, using only what graded code may call: doctest's summary line followed by 100,000
// spaces (what made the old grader's std::regex recurse once per character until its stack
// overflowed), then a fake summary.
#include <cstdio>
#include <string>

#include "attack.h"

void hostileAttack() {
    static bool done = false;
    if (done) return;
    done = true;
    const std::string bomb = "[doctest] test cases:" + std::string(100000, ' ') + "1 | 1 passed | 0 failed\n";
    std::fputs(bomb.c_str(), stdout);
    std::fputs(kFakeSummary, stdout);
    std::fflush(stdout);
}
