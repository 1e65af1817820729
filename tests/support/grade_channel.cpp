// The harness's side of the grader's result channel (grade_channel.h). Linux only: elsewhere the
// test programs are ordinary doctest programs (the grader runs on Linux alone).
#include "grade_channel.h"

#include <doctest/doctest.h>

#include <sstream>
#include <string>

#if defined(__linux__)
#include <fcntl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstring>

namespace ps::gradechannel {

namespace {

int channel = -1;                    // kFd once the token is taken
char tokenHex[2 * kTokenBytes + 1];  // the token, as every record begins with it

// Takes the token: runs from .preinit_array, before any static constructor of the program (and
// so before any code of a graded file) and before the C and C++ libraries' own initialisation,
// so it reads the environment from its argument and calls nothing but system-call wrappers. A
// channel that gives no token is the grader's fault: say so and stop.
void takeToken(int, char**, char** envp) {
    const size_t n = std::strlen(kEnv);
    bool asked = false;
    for (char** e = envp; e && *e && !asked; ++e)
        asked = std::strncmp(*e, kEnv, n) == 0 && std::strcmp(*e + n, "=3") == 0;
    if (!asked) return;
    unsigned char token[kTokenBytes];
    if (recv(kFd, token, sizeof token, 0) != static_cast<ssize_t>(sizeof token)) {
        const char say[] = "pathspace: the grader's result channel (fd 3) gave no token\n";
        ssize_t written = write(2, say, sizeof say - 1);
        (void)written;
        _exit(3);
    }
    fcntl(kFd, F_SETFD, FD_CLOEXEC);
    static const char digits[] = "0123456789abcdef";
    for (size_t i = 0; i < kTokenBytes; ++i) {
        tokenHex[2 * i] = digits[token[i] >> 4];
        tokenHex[2 * i + 1] = digits[token[i] & 15];
    }
    channel = kFd;
}

[[gnu::section(".preinit_array"), gnu::used]] void (*const takeTokenFirst)(int, char**, char**) = takeToken;

// One record: the token, the head ("end 3 0 0 0 1"), and a text on the next line.
void send(const std::string& head, const std::string& text = "") {
    if (channel < 0) return;
    std::string record = std::string(tokenHex) + " " + head;
    if (!text.empty()) record += "\n" + text;
    if (record.size() > kMaxRecord) record.resize(kMaxRecord);
    ::send(channel, record.data(), record.size(), MSG_NOSIGNAL);
}

// A source file as the test's object names it, without leading "./" and "../" (a build with
// ccache's base folder compiles with relative paths).
std::string sourceName(const char* file) {
    std::string f = file;
    while (f.rfind("./", 0) == 0 || f.rfind("../", 0) == 0) f.erase(0, f.find('/') + 1);
    return f;
}

// A failed assertion as the tests' console reporter words it (doctest_main.cpp): a check that
// carries a message (CHECK_MESSAGE, INFO) gives its message first, then the check; one without,
// doctest's "CHECK( expr ) is NOT correct!" and the values it compared.
std::string describe(const doctest::AssertData& a) {
    std::ostringstream s;
    s << sourceName(a.m_file) << ":" << a.m_line << ": ERROR: ";
    const int n = doctest::IReporter::get_num_active_contexts();
    const doctest::IContextScope* const* contexts = doctest::IReporter::get_active_contexts();
    for (int i = 0; i < n; ++i) {
        s << (i == 0 ? "" : "\n  ");
        contexts[i]->stringify(&s);
    }
    if (n > 0) s << "\n  (";
    s << doctest::assertString(a.m_at) << "( " << a.m_expr << " ) ";
    if (a.m_threw && !(a.m_at & doctest::assertType::is_throws_as) && !(a.m_at & doctest::assertType::is_throws))
        s << "THREW exception: " << a.m_exception.c_str();
    else if (n > 0) s << "failed";
    else s << "is NOT correct!\n  values: " << doctest::assertString(a.m_at) << "( " << a.m_decomp.c_str() << " )";
    if (n > 0) s << ")";
    return s.str();
}

// The listener: doctest calls it for every event of the run, beside the console reporter.
struct Listener : doctest::IReporter {
    explicit Listener(const doctest::ContextOptions&) {}
    void report_query(const doctest::QueryData&) override {}
    void test_run_start() override {}
    void test_run_end(const doctest::TestRunStats& s) override {
        send("run " + std::to_string(s.numTestCasesPassingFilters) + " " + std::to_string(s.numTestCasesFailed) + " " +
             std::to_string(s.numAsserts) + " " + std::to_string(s.numAssertsFailed));
    }
    void test_case_start(const doctest::TestCaseData& tc) override {
        asserts = failed = 0;
        first.clear();
        send("start", tc.m_name);
    }
    void test_case_reenter(const doctest::TestCaseData&) override {}
    void test_case_end(const doctest::CurrentTestCaseStats& s) override {
        send("end " + std::to_string(asserts) + " " + std::to_string(failed) + " " +
                 std::to_string(s.numAssertsFailedCurrentTest) + " " + std::to_string(s.failure_flags) + " " +
                 (s.testCaseSuccess ? "1" : "0"),
             first);
    }
    void test_case_exception(const doctest::TestCaseException& e) override {
        send(std::string("exception ") + (e.is_crash ? "1" : "0"), e.error_string.c_str());
    }
    void subcase_start(const doctest::SubcaseSignature&) override {}
    void subcase_end() override {}
    // Counted here, independently of doctest's counters (which the code under test could reach).
    void log_assert(const doctest::AssertData& a) override {
        ++asserts;
        if (a.m_failed && !(a.m_at & doctest::assertType::is_warn)) fail(describe(a));
    }
    // FAIL, FAIL_CHECK and ADD_FAIL_* are messages that count as failed assertions.
    void log_message(const doctest::MessageData& m) override {
        if (m.m_severity & doctest::assertType::is_warn) return;
        ++asserts;
        fail(sourceName(m.m_file) + ":" + std::to_string(m.m_line) + ": ERROR: " + m.m_string.c_str());
    }
    void test_case_skipped(const doctest::TestCaseData&) override {}

    void fail(const std::string& what) {
        if (++failed == 1) first = what;
    }
    int asserts = 0, failed = 0;
    std::string first;
};

REGISTER_LISTENER("pathspace-grade-channel", 1, Listener);

}  // namespace

int exitStatus(int status) {
    send("exit " + std::to_string(status));
    return status;
}

}  // namespace ps::gradechannel

#else

int ps::gradechannel::exitStatus(int status) { return status; }

#endif
