// Reading CTest's JUnit, writing the table, results.json and junit.xml (report.h).
#include "report.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace grade {

namespace {

std::string xmlUnescape(std::string s) {
    const std::pair<const char*, const char*> ents[] = {{"&quot;", "\""}, {"&apos;", "'"}, {"&lt;", "<"}, {"&gt;", ">"},
                                                        {"&#10;", "\n"},  {"&#13;", "\r"}, {"&amp;", "&"}};
    for (auto [from, to] : ents)
        for (size_t p = 0; (p = s.find(from, p)) != std::string::npos; p += std::string(to).size())
            s.replace(p, std::string(from).size(), to);
    return s;
}

// s with every byte that does not belong to a well-formed UTF-8 sequence replaced by '?':
// a test's output is whatever the submission printed, and JSON and XML readers reject bad UTF-8.
std::string utf8(const std::string& s) {
    std::string out;
    for (size_t i = 0; i < s.size();) {
        const unsigned char c = s[i];
        const size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
        bool ok = n > 0 && i + n <= s.size();
        for (size_t k = 1; ok && k < n; ++k) ok = (static_cast<unsigned char>(s[i + k]) >> 6) == 0x2;
        if (ok && n > 1) {  // no overlong form, no surrogate, nothing above U+10FFFF
            unsigned cp = c & (0xff >> (n + 1));
            for (size_t k = 1; k < n; ++k) cp = (cp << 6) | (static_cast<unsigned char>(s[i + k]) & 0x3f);
            const unsigned least[] = {0, 0, 0x80, 0x800, 0x10000};
            ok = cp >= least[n] && (cp < 0xd800 || cp > 0xdfff) && cp <= 0x10ffff;
        }
        if (ok) out.append(s, i, n), i += n;
        else out += '?', ++i;
    }
    return out;
}

std::string xmlEscape(const std::string& s) {
    std::string out;
    for (char c : utf8(s)) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default:
            if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') out += ' ';
            else out += c;
        }
    }
    return out;
}

std::string jsonEscape(const std::string& s) {
    std::string out;
    for (unsigned char c : utf8(s)) {
        switch (c) {
        case '"': out += "\\\""; break;
        case '\\': out += "\\\\"; break;
        case '\n': out += "\\n"; break;
        case '\t': out += "\\t"; break;
        default:
            if (c < 0x20 || c == 0x7f) {
                char b[8];
                std::snprintf(b, sizeof b, "\\u%04x", c);
                out += b;
            } else out += static_cast<char>(c);
        }
    }
    return out;
}

// The value of attribute `name` in the start tag `tag` ("" if absent).
std::string attribute(const std::string& tag, const std::string& name) {
    const std::string key = " " + name + "=\"";
    const size_t a = tag.find(key);
    if (a == std::string::npos) return "";
    const size_t b = a + key.size(), e = tag.find('"', b);
    return e == std::string::npos ? "" : tag.substr(b, e - b);
}

// What a failed test's report shows: the reason, then what it printed.
std::string feedback(const TestResult& r) {
    if (r.passed) return "";
    return r.message + (r.output.empty() ? "" : "\n" + r.output);
}

// Seconds as a number for JSON and XML: fixed, three decimals.
std::string secondsText(double s) {
    char b[32];
    std::snprintf(b, sizeof b, "%.3f", s);
    return b;
}

// The whole of `text` into `path`, every write checked through the close.
void writeFile(const fs::path& path, const std::string& text) {
    std::ofstream f(path, std::ios::binary);
    f << text;
    f.close();
    if (!f) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace

std::string validUtf8(const std::string& s) { return utf8(s); }

std::string readText(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// "... [3 pts]" or "[1 pt]": the points; 1 when the name says none.
int pointsOf(const std::string& name) {
    for (size_t at = name.find('['); at != std::string::npos; at = name.find('[', at + 1)) {
        size_t i = at + 1;
        while (i < name.size() && std::isdigit(static_cast<unsigned char>(name[i]))) ++i;
        if (i == at + 1 || name.compare(i, 3, " pt") != 0) continue;
        const size_t close = i + 3 + (name.compare(i + 3, 1, "s") == 0 ? 1 : 0);
        if (close < name.size() && name[close] == ']') return std::stoi(name.substr(at + 1, i - at - 1));
    }
    return 1;
}

// The names of the TEST_CASEs in dir's .cpp files, file by file: the string literal after
// "TEST_CASE(", with adjacent literals joined as the compiler joins them (clang-format splits a
// long name into "... " "..." over two lines; escapes are kept as written).
std::vector<std::string> declaredTests(const fs::path& dir) {
    std::vector<std::string> names;
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().extension() == ".cpp") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& f : files) {
        const std::string text = readText(f);
        const auto blanks = [&](size_t i) {
            while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
            return i;
        };
        for (size_t pos = 0; (pos = text.find("TEST_CASE", pos)) != std::string::npos;) {
            pos += 9;
            size_t i = blanks(pos);
            if (i >= text.size() || text[i] != '(') continue;
            std::string name;
            bool literal = false;
            for (i = blanks(i + 1); i < text.size() && text[i] == '"'; i = blanks(i + 1)) {
                for (++i; i < text.size() && text[i] != '"'; ++i) {
                    if (text[i] == '\\' && i + 1 < text.size()) name += text[i++];
                    name += text[i];
                }
                literal = true;
            }
            if (literal) names.push_back(name);
        }
    }
    return names;
}

// Parsed with find(), not std::regex: libstdc++'s regex recurses per character and overflows the
// stack on the megabytes of output a failing skeleton produces.
std::map<std::string, TestResult> readJUnit(const fs::path& file) { return readJUnitText(readText(file)); }

std::map<std::string, TestResult> readJUnitText(const std::string& xml) {
    std::map<std::string, TestResult> out;
    for (size_t pos = 0; (pos = xml.find("<testcase", pos)) != std::string::npos;) {
        const size_t tagEnd = xml.find('>', pos);
        if (tagEnd == std::string::npos) break;
        const std::string tag = xml.substr(pos, tagEnd - pos);
        std::string body;
        size_t next = tagEnd + 1;
        if (xml[tagEnd - 1] != '/') {  // <testcase ...> body </testcase>
            const size_t close = xml.find("</testcase>", tagEnd);
            body = xml.substr(tagEnd + 1, (close == std::string::npos ? xml.size() : close) - tagEnd - 1);
            next = close == std::string::npos ? xml.size() : close;
        }
        pos = next;
        TestResult r;
        r.name = xmlUnescape(attribute(tag, "name"));
        r.seconds = std::atof(attribute(tag, "time").c_str());
        const std::string status = attribute(tag, "status");
        const size_t failure = body.find("<failure");
        r.passed = status == "run" && failure == std::string::npos;
        if (failure != std::string::npos)
            r.message = xmlUnescape(attribute(body.substr(failure, body.find('>', failure) - failure), "message"));
        const size_t so = body.find("<system-out>");
        if (so != std::string::npos) {
            const size_t b = so + std::string("<system-out>").size(), e = body.find("</system-out>", b);
            r.output = xmlUnescape(body.substr(b, (e == std::string::npos ? body.size() : e) - b));
        }
        if (!r.passed && r.message.empty()) r.message = status == "notrun" ? "not run" : "failed";
        out[r.name] = r;
    }
    return out;
}

namespace {

constexpr int kTableWidth = 100, kTableIndent = 16;  // the score table's columns; the test name's column

// The text in lines of at most `width` characters, broken at spaces (a longer word on a line of its
// own, whole).
std::vector<std::string> wrapWords(const std::string& text, int width) {
    // A test's points ("[1 pt]", "[2 pts]") stay on one line: their space is glued for the split.
    std::string glued = text;
    for (size_t p = glued.find(" pt"); p != std::string::npos; p = glued.find(" pt", p + 1))
        if (p > 0 && std::isdigit(static_cast<unsigned char>(glued[p - 1]))) glued[p] = '\x01';
    std::vector<std::string> lines;
    std::string line, word;
    std::istringstream in(glued);
    while (in >> word) {
        if (!line.empty() && int(line.size() + 1 + word.size()) > width) {
            lines.push_back(line);
            line.clear();
        }
        line += (line.empty() ? "" : " ") + word;
    }
    if (!line.empty() || lines.empty()) lines.push_back(line);
    for (std::string& l : lines) std::replace(l.begin(), l.end(), '\x01', ' ');
    return lines;
}

}  // namespace

void writeReport(const std::vector<TestResult>& results, const std::map<std::string, std::string>& notes,
                 const fs::path& out, bool junit, double seconds) {
    int score = 0, maxScore = 0;
    std::map<std::string, std::pair<int, int>> perLesson;
    std::ostringstream tests;
    // The table fits 100 columns: a lesson's name on a line of its own, then per test its points,
    // the result and its whole name, wrapped at spaces; a failed test's reason below, wrapped too.
    std::printf("\n%-6s  %-7s %s\n", "points", "result", "test (the lesson above its tests)");
    for (size_t i = 0; i < results.size(); ++i) {
        const TestResult& r = results[i];
        const int got = r.passed ? r.points : 0;
        score += got;
        maxScore += r.points;
        perLesson[r.lesson].first += got;
        perLesson[r.lesson].second += r.points;
        if (i == 0 || results[i - 1].lesson != r.lesson) std::printf("%s\n", r.lesson.c_str());
        const std::vector<std::string> name = wrapWords(r.name, kTableWidth - kTableIndent);
        for (size_t k = 0; k < name.size(); ++k) {
            if (k == 0)
                std::printf("%3d/%-2d  %-7s %s\n", got, r.points,
                            r.passed     ? "pass"
                            : r.timedOut ? "TIMEOUT"
                                         : "FAIL",
                            name[k].c_str());
            else std::printf("%*s%s\n", kTableIndent, "", name[k].c_str());
        }
        if (!r.passed)
            for (const std::string& line : wrapWords("why: " + r.message, kTableWidth - kTableIndent - 2))
                std::printf("%*s%s\n", kTableIndent + 2, "", line.c_str());
        tests << (i ? ",\n" : "") << "    {\"name\": \"" << jsonEscape(r.lesson + ": " + r.name)
              << "\", \"score\": " << got << ", \"max_score\": " << r.points << ", \"status\": \""
              << (r.passed ? "passed" : "failed") << "\", \"visibility\": \"visible\", \"output\": \""
              << jsonEscape(feedback(r)) << "\", \"extra_data\": {\"execution_time\": " << secondsText(r.seconds)
              << "}}";
    }
    std::printf("\n");
    std::string summary;  // notes[""]: about the submission as a whole (grade --note), first
    if (auto n = notes.find(""); n != notes.end() && !n->second.empty()) summary = n->second + "\n";
    for (const auto& [lesson, s] : perLesson) {
        std::printf("%-16s %d / %d\n", lesson.c_str(), s.first, s.second);
        summary += lesson + ": " + std::to_string(s.first) + " / " + std::to_string(s.second) + "\n";
        if (auto n = notes.find(lesson); n != notes.end() && !n->second.empty()) summary += n->second + "\n";
    }
    std::printf("%-16s %d / %d\n", "total", score, maxScore);
    // stdout (the grader's log, with the host's paths) is for the lecturer only.
    std::ostringstream json;
    json << "{\n  \"score\": " << score << ",\n  \"execution_time\": " << static_cast<long long>(seconds + 0.5)
         << ",\n  \"visibility\": \"visible\",\n  \"stdout_visibility\": \"hidden\""
         << ",\n  \"output\": \"" << jsonEscape(summary) << "\""
         << ",\n  \"extra_data\": {\"max_score\": " << maxScore << "}"
         << ",\n  \"tests\": [\n"
         << tests.str() << (results.empty() ? "" : "\n") << "  ]\n}\n";
    writeFile(out / "results.json", json.str());
    if (!junit) return;
    // One suite per lesson; a test's failure type says why: failure or timeout.
    double allSeconds = 0;
    int allFailures = 0;
    for (const TestResult& r : results) allSeconds += r.seconds, allFailures += !r.passed;
    std::ostringstream x;
    x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"grade\" tests=\"" << results.size()
      << "\" failures=\"" << allFailures << "\" errors=\"0\" skipped=\"0\" time=\"" << secondsText(allSeconds)
      << "\">\n";
    for (const auto& [lesson, s] : perLesson) {
        int count = 0, failures = 0;
        double suiteSeconds = 0;
        for (const TestResult& r : results)
            if (r.lesson == lesson) ++count, failures += !r.passed, suiteSeconds += r.seconds;
        x << "  <testsuite name=\"" << xmlEscape(lesson) << "\" tests=\"" << count << "\" failures=\"" << failures
          << "\" errors=\"0\" skipped=\"0\" time=\"" << secondsText(suiteSeconds) << "\">\n";
        if (auto n = notes.find(lesson); n != notes.end() && !n->second.empty())
            x << "    <system-out>" << xmlEscape(n->second) << "</system-out>\n";
        for (const TestResult& r : results) {
            if (r.lesson != lesson) continue;
            x << "    <testcase classname=\"" << xmlEscape(lesson) << "\" name=\"" << xmlEscape(r.name) << "\" time=\""
              << secondsText(r.seconds) << "\"";
            if (r.passed) {
                x << "/>\n";
                continue;
            }
            x << ">\n      <failure type=\"" << (r.timedOut ? "timeout" : "failure") << "\" message=\""
              << xmlEscape(r.message) << "\">" << xmlEscape(r.output) << "</failure>\n    </testcase>\n";
        }
        x << "  </testsuite>\n";
    }
    x << "</testsuites>\n";
    writeFile(out / "junit.xml", x.str());
}

}  // namespace grade
