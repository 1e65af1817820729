// Hostile submissions' hook into the skeleton: tests/course/hostile.sh copies the skeleton's
// rays.cpp with every PS_TODO(piece, value) rewritten as HOSTILE_PIECE(piece, value), so that each
// unfinished piece, when a test calls it, runs hostileAttack() (defined by the attack's own file)
// and then returns its neutral value: a submission that is wrong everywhere and attacks the
// verdict from a student's piece. It deserves 0.
#pragma once

void hostileAttack();
#define HOSTILE_PIECE(piece, value) (hostileAttack(), value)

// What doctest prints when the one test case it ran passed: what an attack prints instead.
inline const char* const kFakeSummary =
    "[doctest] doctest version is \"2.4.9\"\n"
    "[doctest] run with \"--help\" for options\n"
    "===============================================================================\n"
    "[doctest] test cases: 1 | 1 passed | 0 failed | 17 skipped\n"
    "[doctest] assertions: 1 | 1 passed | 0 failed |\n"
    "[doctest] Status: SUCCESS!\n";
