// The one error type for bad input: its message names the file, the line (if any) and the
// problem, as "file:line: problem". The program prints it and exits with a non-zero code.
#pragma once
#include <stdexcept>
#include <string>

namespace ps {

class InputError : public std::runtime_error {
public:
    explicit InputError(const std::string& msg) : std::runtime_error(msg) {}
    InputError(const std::string& file, int line, const std::string& problem)
        : std::runtime_error(file + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + problem) {}
};

// A bad value of a command-line option that a lesson gives its meaning (an algorithm option,
// integrator.h): the program prints it and exits with status 2, as for any bad command line.
class OptionError : public std::runtime_error {
public:
    explicit OptionError(const std::string& msg) : std::runtime_error(msg) {}
};

}  // namespace ps
