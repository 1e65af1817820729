// Hostile: the records a passed test's harness sends, forged (with a guessed token) and written
// to every file descriptor the process may have inherited, the grader's result channel among
// them; then the summary and _exit(0).
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <string>

#include "attack.h"

std::string hostileTestName();  // dispatch.cpp

void attackFdWrite() {
    const std::string token(32, '0');
    const std::string records[] = {token + " start\n" + hostileTestName(), token + " end 1 0 0 0 1",
                                   token + " run 1 0 1 0", token + " exit 0"};
    for (int fd = 3; fd < 1024; ++fd)
        for (const std::string& r : records) {
            const ssize_t n = write(fd, r.data(), r.size());
            (void)n;
        }
    std::fputs(kFakeSummary, stdout);
    std::fflush(stdout);
    _exit(0);
}
