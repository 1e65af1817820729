// Hostile, using only what graded code may call, next to the reference rays.cpp: in one test
// ("triangle hits report the exact t ..."), a static constructor prints 1 GiB before main(). The
// test deserves its points; the log must keep at most its cap, and the grading go on.
#include <cstdio>
#include <cstring>

namespace {

// glibc calls .init_array functions with main()'s arguments.
[[gnu::constructor]] void flood(int argc, char** argv) {
    if (argc < 2 || !std::strstr(argv[1], "triangle hits report the exact t")) return;
    static char block[1 << 20];
    std::memset(block, 'x', sizeof block);
    for (int i = 0; i < 1024; ++i) std::fwrite(block, 1, sizeof block, stdout);
    std::fflush(stdout);
}

}  // namespace
