// The result channel between a test program and the autograder (tools/grade, README "The
// autograder"): how the grader learns what a graded test did, from a source the code under test
// cannot print to or forge.
//
// The grader runs a test program with one end of a Unix socket pair (SOCK_SEQPACKET: one record
// per message, never two run together) as file descriptor kFd, says so in the environment
// (kEnv=3), and first sends a fresh random token of kTokenBytes. The harness (grade_channel.cpp,
// linked into every test program's main) takes the token before any other code of the program
// runs (a .preinit_array entry: before every static constructor), and from then on sends, from
// doctest's listener interface, one record per event, each beginning with the token in hex:
//   TOKEN start\nNAME                                  a test case started
//   TOKEN exception CRASH\nTEXT                        it threw (or crashed, CRASH = 1)
//   TOKEN end ASSERTS FAILED DOCTEST_FAILED FLAGS OK\nFIRST FAILURE
//                                                      it ended: asserts and failed ones as the
//                                                      harness counted them, doctest's own count
//                                                      of failed ones, doctest's failure flags,
//                                                      doctest's verdict (1/0); then the first
//                                                      failed assertion as doctest reports it
//   TOKEN run PASSING_FILTERS FAILED ASSERTS ASSERTS_FAILED   the run ended (doctest's counts)
//   TOKEN exit STATUS                                  main() returns STATUS
// Every record is at most kMaxRecord bytes (a long name or text is cut). Without kEnv the
// harness sends nothing and the program is an ordinary doctest program.
#pragma once
#include <cstddef>

namespace ps::gradechannel {

constexpr int kFd = 3;
constexpr const char* kEnv = "PATHSPACE_GRADE_CHANNEL";
constexpr std::size_t kTokenBytes = 16;
constexpr std::size_t kMaxRecord = 8192;

// main()'s last word: the status it returns (sends the exit record when there is a channel).
int exitStatus(int status);

}  // namespace ps::gradechannel
