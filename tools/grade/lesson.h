// Grading one lesson of a submission from the prepared tree (cmake/grader.cmake):
//  1. copy the submission's files of that lesson (regular .cpp and .h files with plain names; a
//     symbolic link, or a .cpp named like the lesson's plumbing, is left out and said so) into
//     a private work folder;
//  2. build: compile them and link them with the tree's objects (rules/lesson.mk), one step with
//     a time limit, in the sandbox (sandbox.h) that shows the copy, the build folder and the parts
//     of the tree a build needs, but not the reference of the lesson being graded;
//  3. run each graded test (the tree's tests/NN.txt) alone, as its own step with a time limit, in
//     a sandbox that shows the test program (read-only), the data tests read and a scratch folder.
// A test passes when its program exits 0 AND doctest's summary says exactly one test case ran
// and passed (a name that selected nothing, or a program that exits early, is not a pass).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "report.h"
#include "sandbox.h"

namespace grade {

struct Grading {
    std::filesystem::path tree;        // the prepared tree
    std::filesystem::path submission;  // lesson folders NN-name/
    std::filesystem::path work;        // private work folders, one per lesson
    std::filesystem::path logs;        // OUT/logs: every step's output, for the lecturer
    double testTimeout = 120, buildTimeout = 300;
    int jobs = 2;
    Sandbox sandbox;  // off: --no-sandbox
};

// The graded tests of `lesson` (e.g. "02-direct-mis"), scored; `note` gets what the grader has
// to say about the lesson as a whole (files left out, the build's failure). In the messages, the
// outputs and the note the grader's own paths are replaced by neutral names: the submission's
// files by the lesson's name ("02-direct-mis/mis.cpp"), the tree by "grader", the work folder by
// "work", the reference's sources relative to the repository (OUT/logs keep the real paths).
std::vector<TestResult> gradeLesson(const Grading& g, const std::string& lesson, std::string& note);

// What every sandboxed step may read of the tree while `lesson` is graded (Sandbox::probe).
View treeView(const Grading& g, const std::string& lesson);

}  // namespace grade
