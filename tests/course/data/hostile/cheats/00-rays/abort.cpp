// Hostile: the summary of a passed test, then abort() from a student's piece.
#include <cstdio>
#include <cstdlib>

#include "attack.h"

void attackAbort() {
    std::fputs(kFakeSummary, stdout);
    std::fflush(stdout);
    std::abort();
}
