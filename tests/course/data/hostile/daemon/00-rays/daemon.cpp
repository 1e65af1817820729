// Hostile: next to the reference rays.cpp, code that starts a detached process when the test
// program starts (fork, setsid, fork again, ignore hang-ups): for 6 seconds it keeps rewriting
// OUT/results.json to 999 of 999 points, so that whatever the grader writes at the end is
// replaced. The grader must kill it with the step that started it.
#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cstring>

#include "paths.h"  // written by tests/course/hostile.sh: HOSTILE_OUT

namespace {

const bool detached = [] {
    if (fork() != 0) return true;  // the test goes on
    setsid();
    if (fork() != 0) _exit(0);
    signal(SIGHUP, SIG_IGN);
    signal(SIGTERM, SIG_IGN);
    const char* fake = "{\"score\": 999, \"max_score\": 999, \"tests\": []}\n";
    for (int i = 0; i < 60; ++i) {
        const int fd = open(HOSTILE_OUT "/results.json", O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0) {
            ssize_t n = write(fd, fake, std::strlen(fake));
            (void)n;
            close(fd);
        }
        usleep(100000);
    }
    _exit(0);
}();

}  // namespace
