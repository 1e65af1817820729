// main() of every test program: doctest's, after choosing passive waiting for the render
// loop's threads (framework/passive_wait.h: tests run two at a time and must not spin each other out).
// A listener tells the statistics helpers which test runs: a failed image test names its images
// after it (statistics.h, writeFailedImages).
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>
#include <string>
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

}  // namespace

REGISTER_LISTENER("test-name", 1, TestNameListener);

int main(int argc, char** argv) {
    ps::preferPassiveWaiting(argv);
    return doctest::Context(argc, argv).run();
}
