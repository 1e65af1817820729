// The verdict on a graded test from its result channel (verdict.h).
#include "verdict.h"

#include <charconv>

namespace grade {

namespace {

struct KindName {
    const char* name;
    Record::Kind kind;
    size_t numbers;
};
const KindName kKinds[] = {{"start", Record::Start, 0},
                           {"exception", Record::Exception, 1},
                           {"end", Record::End, 5},
                           {"run", Record::Run, 4},
                           {"exit", Record::Exit, 1}};

// The first line of s, at most 1000 bytes of it.
std::string firstLine(const std::string& s) {
    std::string l = s.substr(0, s.find('\n'));
    if (l.size() > 1000) l = l.substr(0, 1000) + "...";
    return l;
}

}  // namespace

std::optional<Record> parseRecord(const std::string& message, const std::string& token) {
    if (token.empty() || message.size() <= token.size() || message.compare(0, token.size(), token) != 0 ||
        message[token.size()] != ' ')
        return std::nullopt;
    const size_t newline = message.find('\n');
    const std::string head =
        message.substr(token.size() + 1, newline == std::string::npos ? std::string::npos : newline - token.size() - 1);
    Record r;
    if (newline != std::string::npos) r.text = message.substr(newline + 1);
    std::vector<std::string> words;
    for (size_t p = 0; p <= head.size();) {
        const size_t space = head.find(' ', p);
        words.push_back(head.substr(p, space == std::string::npos ? std::string::npos : space - p));
        if (space == std::string::npos) break;
        p = space + 1;
    }
    for (const KindName& k : kKinds) {
        if (words.front() != k.name) continue;
        if (words.size() != k.numbers + 1) return std::nullopt;
        r.kind = k.kind;
        for (size_t i = 1; i < words.size(); ++i) {
            long long v = 0;
            const std::string& w = words[i];
            const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
            if (w.empty() || ec != std::errc() || end != w.data() + w.size()) return std::nullopt;
            r.numbers.push_back(v);
        }
        return r;
    }
    return std::nullopt;
}

Verdict judge(const Outcome& o, const std::string& name, double timeout, bool sandboxed) {
    Verdict v;
    if (o.timedOut) {
        v.timedOut = true;
        v.message = o.describe(timeout);
        return v;
    }
    if (!o.error.empty()) {
        v.message = o.error;
        return v;
    }
    // bwrap reports a command killed by signal N as exit status 128 + N.
    if (o.signal || (sandboxed && o.exitCode > 128 && o.exitCode < 128 + 65)) {
        Outcome killed = o;
        killed.signal = o.signal ? o.signal : o.exitCode - 128;
        v.message = "crashed: " + killed.describe(timeout);
        return v;
    }
    const std::string status = o.describe(timeout);
    if (o.channelOverflow) {
        v.message = "the test program sent more to the grader's result channel than a test can (" + status + ")";
        return v;
    }
    std::vector<Record> records;
    size_t forged = 0;
    for (const std::string& m : o.channel) {
        if (std::optional<Record> r = parseRecord(m, o.token)) records.push_back(*r);
        else ++forged;
    }
    if (forged > 0) {
        v.message = std::to_string(forged) +
                    " message(s) on the grader's result channel that the test harness did not "
                    "send: not graded (" +
                    status + ")";
        return v;
    }
    // The records in the one order the harness sends them: start, exceptions, end, run, exit.
    const Record *start = nullptr, *exception = nullptr, *end = nullptr, *run = nullptr, *exit = nullptr;
    int starts = 0;
    bool ordered = true;
    for (const Record& r : records) {
        switch (r.kind) {
        case Record::Start:
            ++starts;
            ordered = ordered && !start && !end && !run && !exit;
            start = &r;
            break;
        case Record::Exception:
            ordered = ordered && start && !end;
            if (!exception) exception = &r;
            break;
        case Record::End:
            ordered = ordered && start && !end;
            end = &r;
            break;
        case Record::Run:
            ordered = ordered && !run && !exit && (start == nullptr) == (end == nullptr);
            run = &r;
            break;
        case Record::Exit:
            ordered = ordered && !exit && run;
            exit = &r;
            break;
        }
    }
    if (starts > 1) {
        v.message = "the test's name selected " + std::to_string(starts) + " test cases, not 1";
        return v;
    }
    if (!ordered) {
        v.message = "the grader's result channel holds the test harness's records out of order (" + status + ")";
        return v;
    }
    if (!start) {
        v.message = run && run->numbers[0] == 0 ? "the test's name selected no test case"
                                                : "the test program ended before the test started (" + status + ")";
        return v;
    }
    if (start->text != name) {
        v.message = "the test program ran '" + firstLine(start->text) + "', not this test";
        return v;
    }
    if (exception) {
        v.message = std::string(exception->numbers[0] ? "crashed: " : "threw: ") + firstLine(exception->text);
        return v;
    }
    if (!end) {
        v.message = "the test program ended before the test finished (" + status + ")";
        return v;
    }
    // end: asserts, failed (the harness's count), failed (doctest's), failure flags, success.
    const std::vector<long long>& e = end->numbers;
    if (e[1] != 0 || e[2] != 0 || e[3] != 0 || e[4] != 1) {
        // The first failed assertion as doctest words it (its first line), else what the counts say.
        v.message = firstLine(end->text);
        if (v.message.empty())
            v.message = e[1] == 0 && e[2] != 0 ? "doctest counted failed assertions that the test harness did not see"
                                               : "failed (doctest's failure flags " + std::to_string(e[3]) + ")";
        return v;
    }
    if (!run) {
        v.message = "the test program ended after the test but before doctest's summary (" + status + ")";
        return v;
    }
    // run: test cases run, failed, asserts, failed asserts.
    if (run->numbers[0] != 1 || run->numbers[1] != 0 || run->numbers[3] != 0) {
        v.message = "doctest's summary of the run disagrees with the test's end (" + std::to_string(run->numbers[0]) +
                    " run, " + std::to_string(run->numbers[1]) + " failed)";
        return v;
    }
    if (!exit) {
        v.message = "the test program did not return from main() (" + status + ")";
        return v;
    }
    if (exit->numbers[0] != 0 || o.exitCode != 0) {
        v.message = "the test passed, but the program ended with " + status + " (main() returned " +
                    std::to_string(exit->numbers[0]) + ")";
        return v;
    }
    v.passed = true;
    return v;
}

}  // namespace grade
