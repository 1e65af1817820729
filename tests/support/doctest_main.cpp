// main() of every test program: doctest's, after choosing passive waiting for the render
// loop's threads (framework/passive_wait.h: tests run two at a time and must not spin each other out).
// A listener tells the statistics helpers which test runs: a failed image test names its images
// after it (statistics.h, writeFailedImages). The console reporter puts the reason first: a failed
// CHECK_MESSAGE prints "file:line: ERROR: <what the test says>" and then, in brackets, the check
// itself (doctest's own first line is "CHECK( x ) is NOT correct!", which says nothing).
// Under the autograder, main's status also goes to the grader's result channel (grade_channel.h).
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>
#include <algorithm>
#include <sstream>
#include <string>
#include "grade_channel.h"
#include "passive_wait.h"

namespace ps::stats {
void setCurrentTestName(const std::string& name);  // statistics.h (test_support)
}

namespace {

struct TestNameListener : doctest::IReporter {
    explicit TestNameListener(const doctest::ContextOptions&) {}
    void report_query(const doctest::QueryData&) override {}
    void test_run_start() override {}
    void test_run_end(const doctest::TestRunStats&) override {}
    void test_case_start(const doctest::TestCaseData& tc) override { ps::stats::setCurrentTestName(tc.m_name); }
    void test_case_reenter(const doctest::TestCaseData&) override {}
    void test_case_end(const doctest::CurrentTestCaseStats&) override {}
    void test_case_exception(const doctest::TestCaseException&) override {}
    void subcase_start(const doctest::SubcaseSignature&) override {}
    void subcase_end() override {}
    void log_assert(const doctest::AssertData&) override {}
    void log_message(const doctest::MessageData&) override {}
    void test_case_skipped(const doctest::TestCaseData&) override {}
};

// doctest's console reporter (defined in this file, with the implementation), with two changes:
// a failed check that carries a message prints the message on its first line, and a test prints
// at most about a screen of failures (kMaxLines): a wrong formula fails the same check many times,
// and the first few say what is wrong. The rest are counted in one line at the end.
struct ReasonFirstReporter : doctest::ConsoleReporter {
    static constexpr int kMaxLines = 30;
    int linesShown = 0, hidden = 0;

    using ConsoleReporter::ConsoleReporter;

    void test_case_start(const doctest::TestCaseData& in) override {
        linesShown = hidden = 0;
        ConsoleReporter::test_case_start(in);
    }
    void test_case_end(const doctest::CurrentTestCaseStats& st) override {
        if (hidden > 0)
            s << "... and " << hidden << " more failed check" << (hidden > 1 ? "s" : "")
              << " of this test, not shown (the first ones above say what is wrong)\n\n";
        ConsoleReporter::test_case_end(st);
    }
    void log_assert(const doctest::AssertData& rb) override {
        if (!rb.m_failed || tc->m_no_output) return ConsoleReporter::log_assert(rb);
        shown([&] {
            const int n = get_num_active_contexts();
            if (n == 0) return ConsoleReporter::log_assert(rb);
            DOCTEST_LOCK_MUTEX(mutex)
            logTestStart();
            file_line_to_stream(rb.m_file, rb.m_line, " ");
            successOrFailColoredStringToStream(false, rb.m_at);
            const doctest::IContextScope* const* contexts = get_active_contexts();
            for (int i = 0; i < n; ++i) {
                s << (i == 0 ? "" : "  ");
                contexts[i]->stringify(&s);
                s << "\n";
            }
            s << "  (" << doctest::assertString(rb.m_at) << "( " << rb.m_expr << " ) failed)\n\n";
        });
    }
    void log_message(const doctest::MessageData& mb) override {
        if (tc->m_no_output) return;
        shown([&] { ConsoleReporter::log_message(mb); });
    }

    // Runs print (which writes to s) into a buffer and shows it unless the test has shown its screen.
    template <class Print>
    void shown(Print&& print) {
        std::ostringstream buffer;
        std::streambuf* out = s.rdbuf(buffer.rdbuf());
        print();
        s.rdbuf(out);
        const std::string text = buffer.str();
        const int lines = int(std::count(text.begin(), text.end(), '\n'));
        if (linesShown > 0 && linesShown + lines > kMaxLines) {
            ++hidden;
            return;
        }
        linesShown += lines;
        s << text;
    }
};

}  // namespace

REGISTER_LISTENER("test-name", 1, TestNameListener);
REGISTER_REPORTER("pathspace", 1, ReasonFirstReporter);

int main(int argc, char** argv) {
    ps::preferPassiveWaiting(argv);
    doctest::Context context;
    context.setOption("reporters", "pathspace");  // the default; --reporters=... on the command line wins
    context.applyCommandLine(argc, argv);
    return ps::gradechannel::exitStatus(context.run());
}
