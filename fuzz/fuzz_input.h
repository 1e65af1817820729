// What every fuzz target shares: the fuzzer's bytes as a file on disk (the readers take paths),
// and the rule of the game — bad input may only ever end in ps::InputError. Any other exception,
// a crash, a hang (libFuzzer's -timeout) or a sanitizer report is a finding.
#pragma once
#include <unistd.h>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include "errors.h"

namespace psfuzz {

// A scratch file of this process, rewritten for every input.
inline std::string scratchPath(const std::string& name) {
    return "/tmp/pathspace-fuzz-" + std::to_string(getpid()) + "-" + name;
}

inline std::string writeScratch(const std::string& name, const uint8_t* data, size_t size) {
    const std::string path = scratchPath(name);
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data), std::streamsize(size));
    return path;
}

// Runs f; InputError is the expected outcome of bad input, anything else aborts (a finding).
template <class F>
void expectOnlyInputError(F&& f) {
    try {
        f();
    } catch (const ps::InputError& e) {
        const std::string msg = e.what();
        // One line, no raw control bytes: the message goes to a student's terminal.
        for (char c : msg)
            if (c == '\n' || c == '\0') {
                std::fprintf(stderr, "InputError message holds a newline or NUL byte: %s\n", msg.c_str());
                std::abort();
            }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "not an InputError: %s\n", e.what());
        std::abort();
    }
}

}  // namespace psfuzz
