// Grading one lesson of a submission from the prepared tree (cmake/grader.cmake):
//  1. copy the submission's files of that lesson (regular .cpp and .h files with plain names, at
//     most kMaxFiles of at most kMaxFileBytes; a symbolic link, or a .cpp named like the lesson's
//     plumbing, is left out and said so) into a private work folder;
//  2. compile them (rules/lesson.mk), one step with a time limit, in the sandbox (sandbox.h)
//     that shows the copy, the build folder and the parts of the tree a build needs, but not the
//     reference of the lesson being graded;
//  3. the object check (objcheck.h): objdump disassembles the objects (a sandboxed step), the
//     grader reads them and refuses the lesson when they use, define or hold what graded code
//     may not (unless --no-object-check);
//  4. link them with the tree's objects (the tree's first, so that its copies of shared inline
//     code are the ones used);
//  5. run each graded test (the tree's tests/NN.txt) alone, as its own step with a time limit, in
//     a sandbox that shows the test program (read-only), the data tests read and an empty memory
//     file system as its scratch folder, with the grader's result channel (grade_channel.h).
// A test passes only as its channel says (verdict.h): what it printed is its log, never its score.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "report.h"
#include "sandbox.h"

namespace grade {

// What a grading may write and keep (README, "The autograder": "What a grade writes").
constexpr std::uint64_t kStepLog = 1 << 20;            // one step's log in OUT/logs
constexpr std::uint64_t kMinStepLog = 4 << 10;         // ... when the budgets below are spent
constexpr std::uint64_t kLessonLogs = 16 << 20;        // one lesson's logs
constexpr std::uint64_t kAllLogs = 64 << 20;           // all of OUT/logs
constexpr size_t kMaxFiles = 32;                       // files copied from a lesson's folder
constexpr std::uint64_t kMaxFileBytes = 1 << 20;       // ... each at most
constexpr std::uint64_t kBuildFileBytes = 64 << 20;    // any file the build writes
constexpr std::uint64_t kScratchBytes = 64 << 20;      // a test's scratch file system (memory)
constexpr std::uint64_t kDisassemblyBytes = 64 << 20;  // objdump's text of the objects
constexpr size_t kNoteBytes = 8 << 10;                 // the grader's note on a lesson, in the reports

struct Grading {
    std::filesystem::path tree;        // the prepared tree
    std::filesystem::path submission;  // lesson folders NN-name/
    std::filesystem::path work;        // private work folders, one per lesson (removed after it)
    std::filesystem::path logs;        // OUT/logs: every step's output, for the lecturer
    double testTimeout = 120, buildTimeout = 300;
    int jobs = 2;
    Sandbox sandbox;                     // off: --no-sandbox
    bool objectCheck = true;             // off: --no-object-check
    bool keepWork = false;               // --keep-work
    std::uint64_t logBudget = kAllLogs;  // what OUT/logs may still take
};

// The graded tests of `lesson` (e.g. "02-direct-mis"), scored; `note` gets what the grader has
// to say about the lesson as a whole (files left out, the build's failure, the object check's
// findings). In the messages, the outputs and the note the grader's own paths are replaced by
// neutral names: the submission's files by the lesson's name ("02-direct-mis/mis.cpp"), the tree
// by "grader", the work folder by "work", the reference's sources relative to the repository
// (OUT/logs keep the real paths).
std::vector<TestResult> gradeLesson(Grading& g, const std::string& lesson, std::string& note);

// What every sandboxed step may read of the tree while `lesson` is graded (Sandbox::probe).
View treeView(const Grading& g, const std::string& lesson);

// What a test printed, as its report shows it: all of it up to 16 KiB, else its start and end.
std::string clip(const std::string& s);

// `text` with the grader's paths replaced by neutral names (pairs: path, name; longest first).
std::string neutral(std::string text, const std::vector<std::pair<std::string, std::string>>& names);

}  // namespace grade
