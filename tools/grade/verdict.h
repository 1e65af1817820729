// The verdict on one graded test (README "The autograder", threat model), from the records of the
// grader's result channel (tests/support/grade_channel.h) and the step's outcome; never from
// what the test printed, which the code under test can print too. No regular expression reads
// anything here: a record is split at its spaces and its first newline, numbers are read with
// std::from_chars, and a record that is not exactly as the harness writes it is a forgery.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "process.h"

namespace grade {

struct Record {
    enum Kind { Start, Exception, End, Run, Exit };
    Kind kind = Start;
    std::vector<long long> numbers;  // the head's numbers, as many as the kind has
    std::string text;                // after the first newline (a name, a failure)
};

// One message of the channel as a record: none unless it begins with the token (hex), a space
// and a kind the harness sends, with that kind's count of whole numbers and nothing else.
std::optional<Record> parseRecord(const std::string& message, const std::string& token);

struct Verdict {
    bool passed = false;
    bool timedOut = false;
    std::string message;  // why it failed, one line
};

// Whether the graded test `name` passed: its step ended by itself with status 0, and the
// channel holds exactly, in this order and all with the token: "start NAME"; "end" with no failed
// assertion by the harness's count nor by doctest's, no failure flag and doctest's verdict
// success; "run" with one test case run and none failed; "exit 0". Nothing else: a second test
// case, an exception, a message without the token, more than a test can send — each is a fail,
// named in the message. `sandboxed`: bwrap reports a command killed by signal N as status 128 + N.
Verdict judge(const Outcome& outcome, const std::string& name, double timeout, bool sandboxed);

}  // namespace grade
