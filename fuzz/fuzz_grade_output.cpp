// Fuzz target: everything the grader reads that a submission can shape (tools/grade): the
// records of the result channel and the verdict on them (verdict.h), a test's output as the
// reports show it (clip, neutral names, valid UTF-8), a JUnit report (report.h), objdump's text
// and the object and archive readers of the object check (objcheck.h). The rules of the game:
// no crash, no hang, no sanitizer report; the ELF and ar readers end only in std::runtime_error;
// a verdict says "passed" only for a run that ended with status 0 and whose channel holds
// exactly the four records of one passed test, each with the token.
//
// The input: one byte of flags (exit status 0 or 1, a signal, a timeout, bwrap's statuses, an
// overflowing channel), then fields separated by '\x01': the test's name, then the channel's
// messages, where a leading '~' stands for the token and a space (so that the fuzzer finds
// authentic records); the whole input is also the output, the report, the disassembly and the
// object file.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "lesson.h"
#include "objcheck.h"
#include "report.h"
#include "verdict.h"

namespace {

const std::string kToken = "00112233445566778899aabbccddeeff";

[[noreturn]] void finding(const char* what) {
    std::fprintf(stderr, "fuzz_grade_output: %s\n", what);
    std::abort();
}

template <class F>
void onlyRuntimeErrors(F&& f) {
    try {
        f();
    } catch (const std::runtime_error&) {
    } catch (...) { finding("a reader threw something other than std::runtime_error"); }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    if (text.empty()) return 0;

    // The verdict.
    const unsigned flags = static_cast<unsigned char>(text[0]);
    grade::Outcome o;
    o.exitCode = flags & 1 ? 1 : 0;
    if (flags & 2) o.signal = 11;
    o.timedOut = flags & 4;
    if (flags & 8) o.exitCode = 139;  // what bwrap reports for a command killed by SIGSEGV
    o.channelOverflow = flags & 16;
    o.token = kToken;
    std::vector<std::string> fields;
    for (size_t p = 1; p <= text.size();) {
        const size_t end = text.find('\x01', p);
        fields.push_back(text.substr(p, end == std::string::npos ? std::string::npos : end - p));
        if (end == std::string::npos) break;
        p = end + 1;
    }
    const std::string name = fields.front();
    for (size_t i = 1; i < fields.size(); ++i)
        o.channel.push_back(!fields[i].empty() && fields[i][0] == '~' ? kToken + " " + fields[i].substr(1) : fields[i]);
    for (bool sandboxed : {false, true}) {
        const grade::Verdict v = grade::judge(o, name, 10, sandboxed);
        if (v.passed) {
            if (o.exitCode != 0 || o.signal || o.timedOut || o.channelOverflow) finding("a pass for a run that failed");
            if (o.channel.size() != 4) finding("a pass without exactly four records");
            for (const std::string& m : o.channel)
                if (m.compare(0, kToken.size() + 1, kToken + " ") != 0)
                    finding("a pass with a record without the token");
            if (!v.message.empty()) finding("a pass with a message");
        } else if (v.message.empty()) {
            finding("a fail without a message");
        }
    }
    for (const std::string& m : o.channel) (void)grade::parseRecord(m, kToken);

    // The output as the reports show it.
    const std::string shown = grade::clip(text);
    if (shown.size() > (16 << 10) + 64) finding("clip kept more than 16 KiB");
    const std::string valid = grade::validUtf8(grade::neutral(shown, {{"/tmp/work/", "work/"}, {"/tmp", "tmp"}}));
    if (grade::validUtf8(valid) != valid) finding("validUtf8 is not idempotent");

    // A JUnit report, objdump's text, an object file, an archive.
    (void)grade::readJUnitText(text);
    (void)grade::checkDisassembly(text);
    onlyRuntimeErrors([&] { (void)grade::readElf(text); });
    onlyRuntimeErrors([&] { (void)grade::readArchive(text); });
    return 0;
}
