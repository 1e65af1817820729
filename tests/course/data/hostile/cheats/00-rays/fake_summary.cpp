// Hostile: doctest's summary of a passed test, then _exit(0) from inside a student's piece (the
// trick that scored full marks when the grader read the summary).
#include <unistd.h>

#include <cstdio>

#include "attack.h"

void attackFakeSummary() {
    std::fputs(kFakeSummary, stdout);
    std::fflush(stdout);
    _exit(0);
}
