// report_check: the grader's two reports against the formats their readers expect.
//
//   report_check RESULTS.json [JUNIT.xml] [--forbid TEXT]...
//
// RESULTS.json against Gradescope's published results format (gradescope-autograders.readthedocs.io,
// "Autograder Specifications"): the keys it defines and no other, each of its type, visibility
// one of visible/hidden/after_due_date/after_published, status passed/failed, output formats
// text/html/simple_format/md/ansi; and the grader's own rules: the score is the sum of the
// tests' scores, a test scores 0..max_score and has passed exactly when it scored max_score.
// JUNIT.xml as CI systems read JUnit XML: <testsuites> (or one <testsuite>) of <testsuite> with
// name, tests, failures, errors, skipped and time; <testcase> with name, classname and time, and
// at most one <failure>, <error> or <skipped>; every count equal to what the suite holds; and the
// same tests as RESULTS.json (the grader's rule: suite and classname = the lesson, the part of the
// JSON name before ": "), failed in one exactly when in the other.
// --forbid TEXT: no text of either report may contain TEXT (the grader's own paths).
// Both files are read strictly (json.h, xml.h). Exit status 0 when valid; 1 when not, with one
// line per problem on stderr naming the file and the place; 2 for a bad command line or a file
// that cannot be read.
#include <cctype>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "json.h"
#include "xml.h"

using namespace reportcheck;

namespace {

std::vector<std::string> problems;
void problem(const std::string& file, const std::string& where, const std::string& what) {
    problems.push_back(file + ": " + where + ": " + what);
}

// A number as the document would write it: 3, 0.5.
std::string num(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%g", v);
    return b;
}

bool oneOf(const std::string& v, const std::set<std::string>& allowed) { return allowed.count(v) > 0; }
std::string listed(const std::set<std::string>& s) {
    std::string out;
    for (const std::string& v : s) out += (out.empty() ? "" : ", ") + v;
    return out;
}
const std::set<std::string> kVisibility = {"visible", "hidden", "after_due_date", "after_published"};
const std::set<std::string> kFormats = {"text", "html", "simple_format", "md", "ansi"};
const std::set<std::string> kStatus = {"passed", "failed"};

// Every string in `v` (keys and values), for the --forbid check.
void strings(const Json& v, const std::string& where, std::vector<std::pair<std::string, std::string>>& out) {
    if (v.kind == Json::String) out.push_back({where, v.text});
    for (size_t i = 0; i < v.items.size(); ++i) strings(v.items[i], where + "[" + std::to_string(i) + "]", out);
    for (const auto& [k, m] : v.members)
        out.push_back({where, k}), strings(m, where.empty() ? k : where + "." + k, out);
}

struct Field {
    Json::Kind kind;
    const std::set<std::string>* values = nullptr;  // for a string: the values allowed
};

// The object's keys against `fields` (the published ones): each known, of its type and value.
void fields(const std::string& file, const std::string& where, const Json& v,
            const std::map<std::string, Field>& fields) {
    for (const auto& [key, m] : v.members) {
        auto f = fields.find(key);
        if (f == fields.end()) {
            problem(file, where, "\"" + key + "\" is not a field of the format");
            continue;
        }
        if (m.kind != f->second.kind) {
            problem(file, where + "." + key,
                    std::string("is ") + kindName(m.kind) + ", must be " + kindName(f->second.kind));
            continue;
        }
        if (f->second.values && !oneOf(m.text, *f->second.values))
            problem(file, where + "." + key, "\"" + m.text + "\" is not one of " + listed(*f->second.values));
    }
}

// What RESULTS.json says about each test: name -> failed.
std::map<std::string, bool> checkResults(const std::string& file, const Json& doc) {
    std::map<std::string, bool> failed;
    if (doc.kind != Json::Object) {
        problem(file, "the document", std::string("is ") + kindName(doc.kind) + ", must be an object");
        return failed;
    }
    fields(file, "top level", doc,
           {{"score", {Json::Number}},
            {"execution_time", {Json::Number}},
            {"output", {Json::String}},
            {"output_format", {Json::String, &kFormats}},
            {"test_output_format", {Json::String, &kFormats}},
            {"test_name_format", {Json::String, &kFormats}},
            {"visibility", {Json::String, &kVisibility}},
            {"stdout_visibility", {Json::String, &kVisibility}},
            {"extra_data", {Json::Object}},
            {"tests", {Json::Array}},
            {"leaderboard", {Json::Array}}});
    if (const Json* t = doc.find("execution_time"); t && t->kind == Json::Number && t->number < 0)
        problem(file, "execution_time", "is negative");
    const Json* tests = doc.find("tests");
    const Json* score = doc.find("score");
    const bool haveTests = tests && tests->kind == Json::Array;
    double sum = 0;
    bool everyScored = haveTests;
    if (haveTests)
        for (size_t i = 0; i < tests->items.size(); ++i) {
            const Json& t = tests->items[i];
            const std::string where = "tests[" + std::to_string(i) + "]";
            if (t.kind != Json::Object) {
                problem(file, where, std::string("is ") + kindName(t.kind) + ", must be an object");
                continue;
            }
            fields(file, where, t,
                   {{"score", {Json::Number}},
                    {"max_score", {Json::Number}},
                    {"status", {Json::String, &kStatus}},
                    {"name", {Json::String}},
                    {"name_format", {Json::String, &kFormats}},
                    {"number", {Json::String}},
                    {"output", {Json::String}},
                    {"output_format", {Json::String, &kFormats}},
                    {"tags", {Json::Array}},
                    {"visibility", {Json::String, &kVisibility}},
                    {"extra_data", {Json::Object}}});
            if (const Json* tags = t.find("tags"))
                for (const Json& tag : tags->items)
                    if (tag.kind != Json::String)
                        problem(file, where + ".tags", "holds something that is not a string");
            // The grader's rules: every test has a name, a score out of max_score, a status.
            const Json *s = t.find("score"), *m = t.find("max_score"), *st = t.find("status"), *n = t.find("name");
            if (!s || s->kind != Json::Number) {
                everyScored = false;
                problem(file, where, "no score");
                continue;
            }
            sum += s->number;
            if (!m || m->kind != Json::Number || !st || st->kind != Json::String || !n || n->kind != Json::String) {
                problem(file, where, "needs name, max_score and status (the grader writes them all)");
                continue;
            }
            if (s->number < 0 || s->number > m->number)
                problem(file, where + ".score", num(s->number) + " is not within 0.." + num(m->number));
            if ((st->text == "passed") != (s->number == m->number))
                problem(file, where + ".status",
                        "\"" + st->text + "\" with " + num(s->number) + " of " + num(m->number) + " points");
            if (failed.count(n->text)) problem(file, where + ".name", "\"" + n->text + "\" twice");
            failed[n->text] = st->text != "passed";
        }
    if (!score && !everyScored) problem(file, "top level", "no score, and not every test has one");
    if (score && score->kind == Json::Number && haveTests && score->number != sum)
        problem(file, "score", num(score->number) + " is not the sum of the tests' scores, " + num(sum));
    return failed;
}

bool wholeNumber(const std::string& s) {
    return !s.empty() && s.size() < 10 && s.find_first_not_of("0123456789") == std::string::npos;
}
// xs:decimal, not negative: digits with at most one point among them.
bool seconds(const std::string& s) {
    size_t digits = 0, points = 0;
    for (char c : s) std::isdigit(static_cast<unsigned char>(c)) ? ++digits : c == '.' ? ++points : points += 2;
    return digits > 0 && points <= 1;
}

// The attribute `key` of `e`, required; "" after a problem.
std::string required(const std::string& file, const Element& e, const std::string& where, const std::string& key) {
    const std::string* v = e.attribute(key);
    if (!v) problem(file, where, "<" + e.name + "> has no " + key + " attribute");
    return v ? *v : "";
}
int count(const std::string& file, const Element& e, const std::string& where, const std::string& key, bool need) {
    const std::string* v = e.attribute(key);
    if (!v) {
        if (need) problem(file, where, "<" + e.name + "> has no " + key + " attribute");
        return -1;
    }
    if (!wholeNumber(*v)) problem(file, where, key + "=\"" + *v + "\" is not a whole number");
    return wholeNumber(*v) ? std::stoi(*v) : -1;
}
void time(const std::string& file, const Element& e, const std::string& where, bool need) {
    const std::string* v = e.attribute("time");
    if (!v && need) problem(file, where, "<" + e.name + "> has no time attribute");
    if (v && !seconds(*v)) problem(file, where, "time=\"" + *v + "\" is not a number of seconds (a decimal)");
}

struct Counts {
    int tests = 0, failures = 0, errors = 0, skipped = 0;
};

// One <testsuite>; its testcases go into `cases` as "suite: name" -> failed (failure or error).
Counts checkSuite(const std::string& file, const Element& s, std::map<std::string, bool>& cases) {
    const std::string where = "<testsuite> at line " + std::to_string(s.line);
    const std::string name = required(file, s, where, "name");
    time(file, s, where, true);
    Counts c;
    for (const Element& e : s.children) {
        if (e.name == "properties" || e.name == "system-out" || e.name == "system-err") continue;
        if (e.name != "testcase") {
            problem(file, where, "<" + e.name + "> cannot be inside a <testsuite>");
            continue;
        }
        const std::string at = "<testcase> at line " + std::to_string(e.line);
        ++c.tests;
        const std::string caseName = required(file, e, at, "name");
        if (const std::string cls = required(file, e, at, "classname"); !cls.empty() && cls != name)
            problem(file, at, "classname \"" + cls + "\" is not its suite's name \"" + name + "\" (the lesson)");
        time(file, e, at, true);
        int outcomes = 0;
        bool bad = false;
        for (const Element& o : e.children) {
            if (o.name == "failure") ++c.failures, ++outcomes, bad = true;
            else if (o.name == "error") ++c.errors, ++outcomes, bad = true;
            else if (o.name == "skipped") ++c.skipped, ++outcomes;
            else if (o.name != "system-out" && o.name != "system-err")
                problem(file, at, "<" + o.name + "> cannot be inside a <testcase>");
            if (!o.children.empty()) problem(file, at, "<" + o.name + "> holds elements; it holds text only");
        }
        if (outcomes > 1) problem(file, at, "more than one of <failure>, <error>, <skipped>");
        const std::string key = name + ": " + caseName;
        if (cases.count(key)) problem(file, at, "the test \"" + caseName + "\" twice in suite \"" + name + "\"");
        cases[key] = bad;
    }
    const std::pair<const char*, int> stated[] = {
        {"tests", c.tests}, {"failures", c.failures}, {"errors", c.errors}, {"skipped", c.skipped}};
    for (const auto& [key, n] : stated) {
        const int v = count(file, s, where, key, true);
        if (v >= 0 && v != n)
            problem(file, where, std::string(key) + "=\"" + std::to_string(v) + "\" but it holds " + std::to_string(n));
    }
    return c;
}

std::map<std::string, bool> checkJUnit(const std::string& file, const Element& root) {
    std::map<std::string, bool> cases;
    if (root.name == "testsuite") {
        checkSuite(file, root, cases);
        return cases;
    }
    if (root.name != "testsuites") {
        problem(file, "the document", "the root is <" + root.name + ">, not <testsuites> or <testsuite>");
        return cases;
    }
    Counts all;
    for (const Element& s : root.children) {
        if (s.name != "testsuite") {
            problem(file, "<testsuites>", "<" + s.name + "> cannot be inside <testsuites>");
            continue;
        }
        const Counts c = checkSuite(file, s, cases);
        all.tests += c.tests, all.failures += c.failures, all.errors += c.errors, all.skipped += c.skipped;
    }
    // <testsuites> may state totals; when it does, they must add up.
    const std::pair<const char*, int> stated[] = {
        {"tests", all.tests}, {"failures", all.failures}, {"errors", all.errors}, {"skipped", all.skipped}};
    for (const auto& [key, n] : stated) {
        const int v = count(file, root, "<testsuites>", key, false);
        if (v >= 0 && v != n)
            problem(file, "<testsuites>",
                    std::string(key) + "=\"" + std::to_string(v) + "\" but its suites hold " + std::to_string(n));
    }
    time(file, root, "<testsuites>", false);
    return cases;
}

// Every attribute value and text of `e` and its children, for the --forbid check.
void texts(const Element& e, std::vector<std::pair<std::string, std::string>>& out) {
    const std::string where = "<" + e.name + "> at line " + std::to_string(e.line);
    for (const auto& [k, v] : e.attributes) out.push_back({where + " " + k, v});
    out.push_back({where, e.text});
    for (const Element& c : e.children) texts(c, out);
}

void forbid(const std::string& file, const std::vector<std::pair<std::string, std::string>>& all,
            const std::vector<std::string>& forbidden) {
    for (const std::string& f : forbidden)
        for (const auto& [where, text] : all) {
            const size_t at = text.find(f);
            if (at == std::string::npos) continue;
            const size_t lineStart = text.rfind('\n', at) == std::string::npos ? 0 : text.rfind('\n', at) + 1;
            const std::string line = text.substr(lineStart, text.find('\n', at) - lineStart);
            problem(file, where, "shows the grader's path \"" + f + "\": " + line.substr(0, 200));
            break;  // one report per forbidden text and file
        }
}

std::string read(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        std::cerr << "report_check: cannot read " << path << "\n";
        std::exit(2);
    }
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> files, forbidden;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--forbid" && i + 1 < argc && argv[i + 1][0]) forbidden.push_back(argv[++i]);
        else if (a.rfind("--", 0) == 0 || files.size() == 2) {
            std::cerr << "usage: report_check RESULTS.json [JUNIT.xml] [--forbid TEXT]...\n";
            return 2;
        } else files.push_back(a);
    }
    if (files.empty()) {
        std::cerr << "usage: report_check RESULTS.json [JUNIT.xml] [--forbid TEXT]...\n";
        return 2;
    }
    std::map<std::string, bool> fromJson, fromXml;
    bool jsonRead = false, xmlRead = false;
    try {
        const std::string text = read(files[0]);
        const Json doc = JsonReader(text).document();
        jsonRead = true;
        fromJson = checkResults(files[0], doc);
        std::vector<std::pair<std::string, std::string>> all;
        strings(doc, "", all);
        forbid(files[0], all, forbidden);
    } catch (const ParseError& e) { problem(files[0], "not JSON", e.what()); }
    if (files.size() == 2) {
        try {
            const std::string text = read(files[1]);
            const Element root = XmlReader(text).document();
            xmlRead = true;
            fromXml = checkJUnit(files[1], root);
            std::vector<std::pair<std::string, std::string>> all;
            texts(root, all);
            forbid(files[1], all, forbidden);
        } catch (const ParseError& e) { problem(files[1], "not XML", e.what()); }
    }
    // The same tests in both, failed in both or in neither.
    if (jsonRead && xmlRead) {
        for (const auto& [name, failed] : fromJson) {
            auto x = fromXml.find(name);
            if (x == fromXml.end()) problem(files[1], "the tests", "no testcase for \"" + name + "\" of " + files[0]);
            else if (x->second != failed)
                problem(files[1], "the tests",
                        "\"" + name + "\" " + (x->second ? "failed" : "passed") + " here, " +
                            (failed ? "failed" : "passed") + " in " + files[0]);
        }
        for (const auto& [name, failed] : fromXml)
            if (!fromJson.count(name)) problem(files[1], "the tests", "\"" + name + "\" is not a test of " + files[0]);
    }
    for (const std::string& p : problems) std::cerr << "report_check: " << p << "\n";
    if (!problems.empty()) return 1;
    std::cout << "report_check: " << files[0] << (files.size() == 2 ? " and " + files[1] : "") << ": valid, "
              << fromJson.size() << " tests\n";
    return 0;
}
