#include "threads.h"
#include <unistd.h>
#include <cstdlib>

namespace ps {

void preferPassiveWaiting(char** argv) {
    if (std::getenv("OMP_WAIT_POLICY") != nullptr) return;
    ::setenv("OMP_WAIT_POLICY", "PASSIVE", 1);
    ::execv("/proc/self/exe", argv);   // returns only on failure: then go on as we are
}

}  // namespace ps
