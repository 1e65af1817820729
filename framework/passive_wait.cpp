#include "passive_wait.h"
#include <cstdlib>
#if defined(__linux__)
#include <unistd.h>
#endif

namespace ps {

void preferPassiveWaiting(char** argv) {
#if defined(__linux__)
    if (std::getenv("OMP_WAIT_POLICY") != nullptr) return;
    ::setenv("OMP_WAIT_POLICY", "PASSIVE", 1);
    ::execv("/proc/self/exe", argv);  // returns only on failure: then go on as we are
#else
    (void)argv;  // no /proc/self/exe (macOS, Windows): set OMP_WAIT_POLICY=PASSIVE yourself
#endif
}

}  // namespace ps
