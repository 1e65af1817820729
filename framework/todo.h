// PS_TODO(piece, value): what an unfinished assignment returns. The first call prints one
// warning naming the piece and the file to edit; the program goes on with `value` (a neutral
// result: no hit, a black colour, a zero pdf), so an untouched skeleton builds, runs and renders.
#pragma once
#include <cstdio>
#include <mutex>

#define PS_TODO(piece, value)                                                                                \
    (                                                                                                        \
        []() {                                                                                               \
            static std::once_flag once_;                                                                     \
            std::call_once(once_, [] {                                                                       \
                std::fprintf(stderr, "pathspace: warning: TODO not done yet: %s (%s:%d)\n", piece, __FILE__, \
                             __LINE__);                                                                      \
            });                                                                                              \
        }(),                                                                                                 \
        value)
