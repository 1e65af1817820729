// Hostile: a static constructor, which runs before main(): in one test it looks for the grader's
// token on every file descriptor (a message of 16 bytes waiting to be read) and, with it, forges
// the records of a passed test; failing that, it prints the summary and calls _exit(0) before
// doctest has started.
#include <sys/socket.h>
#include <unistd.h>

#include <cstdio>
#include <string>

#include "attack.h"

std::string hostileTestName();  // dispatch.cpp

namespace {

const bool early = [] {
    const std::string name = hostileTestName();
    if (name.find("are inverse") == std::string::npos) return true;
    for (int fd = 0; fd < 64; ++fd) {
        unsigned char t[64];
        if (recv(fd, t, sizeof t, MSG_DONTWAIT) != 16) continue;
        std::string token;
        for (unsigned char c : t) {
            if (token.size() == 32) break;
            token += "0123456789abcdef"[c >> 4];
            token += "0123456789abcdef"[c & 15];
        }
        for (const std::string& r :
             {token + " start\n" + name, token + " end 1 0 0 0 1", token + " run 1 0 1 0", token + " exit 0"})
            send(fd, r.data(), r.size(), MSG_NOSIGNAL);
        std::fputs(kFakeSummary, stdout);
        std::fflush(stdout);
        _exit(0);
    }
    std::fputs(kFakeSummary, stdout);
    std::fflush(stdout);
    _exit(0);
}();

}  // namespace
