// The grader's results: one TestResult per graded test, read from a CTest JUnit report (grade
// --junit) or made by tools/grade/lesson.cpp, and written out as the score table, a Gradescope
// results.json and a JUnit XML report.
#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace grade {

struct TestResult {
    std::string lesson, name;
    int points = 1;  // from the name: "... [3 pts]"
    bool passed = false;
    bool timedOut = false;  // stopped by the time limit (message: after how long)
    std::string message;    // why it failed, one line
    std::string output;     // what the test printed (failed tests)
    double seconds = 0;
};

int pointsOf(const std::string& name);

// The graded tests a lesson declares: TEST_CASE("name" ...) in tests/NN-name/*.cpp.
std::vector<std::string> declaredTests(const std::filesystem::path& dir);

// name -> result, from a CTest JUnit file (`ctest --output-junit FILE`). A test CTest stopped at
// its TIMEOUT is marked timedOut.
std::map<std::string, TestResult> readJUnit(const std::filesystem::path& file);
std::map<std::string, TestResult> readJUnitText(const std::string& xml);  // the same, from its text

// Prints the table, writes OUT/results.json (and OUT/junit.xml when `junit`); `notes`: what the
// grader has to say about each lesson (left-out files, a build that failed: once per lesson), and
// under "" about the submission as a whole (first in results.json's output);
// `seconds`: how long the grading took (results.json's execution_time).
// results.json follows Gradescope's published format (top level: score, execution_time, output,
// visibility, stdout_visibility, extra_data, tests; each test: name, score, max_score, status,
// visibility, output, extra_data), with the maximum score and each test's time in extra_data;
// junit.xml the JUnit XML that CI systems read (one testsuite per lesson, each count stated).
// Throws std::runtime_error when a file cannot be written whole.
// Every byte of text that goes into either file is made valid UTF-8 (a test's output is whatever
// the submission printed): see validUtf8.
std::string validUtf8(const std::string& s);

void writeReport(const std::vector<TestResult>& results, const std::map<std::string, std::string>& notes,
                 const std::filesystem::path& out, bool junit, double seconds);

std::string readText(const std::filesystem::path& p);

}  // namespace grade
