// Hostile: next to the reference rays.cpp, code that runs when the test program starts and tries
// to read what it must not see and to write where it must not write. It prints what it managed
// ("snoop: READ", "snoop: WROTE", "snoop: CONNECTED") and what it did not ("snoop: refused").
#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdio>

#include "paths.h"  // written by tests/course/hostile.sh: HOSTILE_SOURCE, HOSTILE_TREE, HOSTILE_OUT, ...

namespace {

void tryRead(const char* path) {
    const int fd = open(path, O_RDONLY);
    char c;
    if (fd >= 0 && read(fd, &c, 1) == 1) std::printf("snoop: READ %s\n", path);
    else std::printf("snoop: refused reading %s\n", path);
    if (fd >= 0) close(fd);
}

void tryWrite(const char* path) {
    const int fd = open(path, O_WRONLY | O_CREAT | O_APPEND, 0644);
    if (fd >= 0 && write(fd, "hostile\n", 8) == 8) std::printf("snoop: WROTE %s\n", path);
    else std::printf("snoop: refused writing %s\n", path);
    if (fd >= 0) close(fd);
}

void tryConnect() {
    const int s = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(53);
    inet_pton(AF_INET, "1.1.1.1", &a.sin_addr);
    if (s >= 0 && connect(s, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0) std::printf("snoop: CONNECTED\n");
    else std::printf("snoop: refused connecting to 1.1.1.1:53\n");
    if (s >= 0) close(s);
}

const bool snooped = [] {
    tryRead(HOSTILE_SOURCE "/solutions/00-rays/rays.cpp");
    tryRead(HOSTILE_SOURCE "/solutions/01-monte-carlo/warps.cpp");
    tryRead(HOSTILE_TREE "/lib/00/reference/rays.o");
    tryRead(HOSTILE_OTHER_SUBMISSION);
    tryWrite(HOSTILE_SOURCE "/HOSTILE-WAS-HERE");
    tryWrite(HOSTILE_TREE "/include/framework/camera.h");
    tryWrite(HOSTILE_TREE "/data/scenes/cornell-box.scene");
    tryWrite(HOSTILE_OUT "/results.json");
    tryWrite(HOSTILE_OUT "/HOSTILE-WAS-HERE");
    char self[4096] = {};
    if (readlink("/proc/self/exe", self, sizeof self - 1) > 0) tryWrite(self);
    tryConnect();
    std::fflush(stdout);
    return true;
}();

}  // namespace
