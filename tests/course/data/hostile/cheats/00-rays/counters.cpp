// Hostile: the test framework's counters overwritten through its public symbols: doctest's
// context (doctest::detail::g_cs, its layout copied from the implementation part of doctest.h)
// has its failure counts set to 0 and an assertion handler that forgets whatever it is given,
// and doctest::is_running_in_test is set to false, so that every assertion from here on is
// handled "outside a test case": not counted, not reported. doctest then reports a pass, and so
// would any listener of doctest's: only the object check, which refuses these names, stops it.
#include <doctest/doctest.h>

#include <atomic>
#include <vector>

#include "attack.h"

namespace doctest::detail {
struct ContextState;
extern ContextState* g_cs;
}  // namespace doctest::detail

namespace {

// doctest 2.4.9's ContextState up to its assertion handler.
struct Lanes {
    struct Line {
        std::atomic<int> count{};
        char padding[64 - sizeof(std::atomic<int>)];
    };
    Line lines[32];
};
struct State : doctest::ContextOptions, doctest::TestRunStats, doctest::CurrentTestCaseStats {
    Lanes asserts, failed;
    std::vector<std::vector<doctest::String>> filters;
    std::vector<doctest::IReporter*> reporters;
    doctest::detail::assert_handler handler;
};

}  // namespace

void attackCounters() {
    State* s = reinterpret_cast<State*>(doctest::detail::g_cs);
    for (Lanes::Line& l : s->failed.lines) l.count = 0;
    s->numAssertsFailed = 0;
    s->numTestCasesFailed = 0;
    s->handler = [](const doctest::AssertData&) {};
    doctest::is_running_in_test = false;
}
