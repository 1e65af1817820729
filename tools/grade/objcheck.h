// The object check (README "The autograder", threat model): before a lesson's test program is
// linked, the grader reads the object files compiled from the submission and refuses the lesson
// when they
//   - use a name (an undefined symbol) that is neither the course's code (the framework, the
//     earlier lessons' reference, the lessons' plumbing, the tests' statistics helpers) nor in
//     the list of what graded code may call (allowedRuntime: math, memory and strings, the
//     standard containers, strings, streams to memory and to the terminal, exceptions, threads):
//     no files, no file descriptors or system calls, no process control, no dynamic loading;
//   - touch the test framework (doctest) or the test harness by name;
//   - define a name that the rest of the test program defines strongly, or a weak one it defines
//     strongly, or any name the rest takes from a library (libc's write, a libstdc++ function):
//     a graded file defines the lesson's pieces and helpers of its own, never a replacement;
//   - define a global name of C linkage (extern "C": the way to replace a C library function);
//   - have sections that run before the harness (.preinit_array, .init, .fini, .ctors, .dtors)
//     or are writable and executable, or symbol or section names with unusual characters;
//   - hold a system-call instruction (syscall, sysenter, int; svc on AArch64), bytes that are no
//     instruction, or a direct jump into the middle of an instruction, in objdump's disassembly.
// Static constructors (.init_array) are allowed: they run after the harness has taken its
// channel's token (tests/support/grade_channel.h) and may call only what any graded code may.
// Everything here reads bytes and text with bounds checks and without regular expressions
// (fuzz/fuzz_grade_output.cpp).
#pragma once
#include <cstdint>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace grade {

struct ElfSymbol {
    std::string name;
    bool defined = false;
    bool weak = false;  // STB_WEAK or STB_GNU_UNIQUE: the linker keeps one copy
};

struct ElfSection {
    std::string name;
    std::uint64_t flags = 0;  // SHF_*
};

struct ElfObject {
    std::vector<ElfSection> sections;
    std::vector<ElfSymbol> globals;  // global and weak symbols, defined or not
};

// The sections and global symbols of an ELF64 little-endian relocatable object (ET_REL);
// throws std::runtime_error saying what is wrong with any other bytes.
ElfObject readElf(const std::string& bytes);

// The ELF objects of an ar archive (lib*.a), in order; throws std::runtime_error.
std::vector<ElfObject> readArchive(const std::string& bytes);

// What the rest of a lesson's test program defines and needs (everything it links but the
// submission's objects), read from the prepared tree.
struct CourseSymbols {
    std::set<std::string> api;            // what graded code may call: defined by the course's code
    std::map<std::string, bool> defined;  // every name the rest defines -> defined strongly somewhere
    std::set<std::string> needed;         // names the rest uses and none of it defines
    std::set<std::string> pieces;         // what the graded lesson's reference defines
};
CourseSymbols courseSymbols(const std::filesystem::path& tree, const std::string& lesson);

struct Finding {
    std::string file;  // the submission's file ("rays.cpp")
    std::string what;  // "calls _exit, which graded code may not use (process control)"
};

// The findings on the submission's objects, named by their source files ("rays.cpp").
std::vector<Finding> checkObjects(const std::vector<std::pair<std::string, ElfObject>>& objects,
                                  const CourseSymbols& course);

// The findings in `objdump -d -z -w` of the submission's objects ("NAME.o: file format" lines
// say which file each part is); files by source name, as above.
std::vector<Finding> checkDisassembly(const std::string& text);

// Whether graded code may use `name`, a symbol no object of the course defines (the C and C++
// runtime): see objcheck.cpp for the list and why.
bool allowedRuntime(const std::string& name);

// The readable form of a symbol ("_exit", "std::cout"); long or odd names shortened.
std::string demangle(const std::string& name);

}  // namespace grade
