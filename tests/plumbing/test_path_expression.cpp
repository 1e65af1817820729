// Tests of lessons/11-classics/path_expression.h, Heckbert's path expressions (lesson 11, Eq. 11.1-11.6):
// the compiled automata against an independent matcher written here (a parse tree matched by
// sets of positions, no automaton), on every string up to a length; the backward automaton and
// its joins on every split of those strings; live states and the longest path against brute
// force; malformed expressions point at the right character.
#include <doctest/doctest.h>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <vector>
#include "11-classics/path_expression.h"

using namespace ps;

namespace {

// ---- the oracle: a parse tree and a matcher by sets of end positions --------------------------
struct Node {
    char kind = 'c';  // 'c' class, '.' sequence, '|' alternatives, '*', '+', '?'
    std::string letters;
    std::vector<std::unique_ptr<Node>> kids;
};

struct OracleParser {
    std::string s;
    size_t i = 0;
    void spaces() {
        while (i < s.size() && s[i] == ' ') ++i;
    }
    std::unique_ptr<Node> alt() {
        auto n = std::make_unique<Node>();
        n->kind = '|';
        n->kids.push_back(seq());
        while ((spaces(), i < s.size() && s[i] == '|')) {
            ++i;
            n->kids.push_back(seq());
        }
        return n;
    }
    std::unique_ptr<Node> seq() {
        auto n = std::make_unique<Node>();
        n->kind = '.';
        while ((spaces(), i < s.size() && s[i] != '|' && s[i] != ')')) {
            std::unique_ptr<Node> a = atom();
            while ((spaces(), i < s.size() && (s[i] == '*' || s[i] == '+' || s[i] == '?'))) {
                auto r = std::make_unique<Node>();
                r->kind = s[i++];
                r->kids.push_back(std::move(a));
                a = std::move(r);
            }
            n->kids.push_back(std::move(a));
        }
        return n;
    }
    std::unique_ptr<Node> atom() {
        auto n = std::make_unique<Node>();
        const char c = s[i++];
        if (c == '(') {
            n = alt();
            ++i;  // ')'
        } else if (c == '.') {
            n->letters = "LDGSE";
        } else if (c == '[') {
            bool negate = s[i] == '^';
            if (negate) ++i;
            std::string in;
            while (s[i] != ']') in += s[i++];
            ++i;
            for (char l : std::string("LDGSE"))
                if ((in.find(l) != std::string::npos) != negate) n->letters += l;
        } else {
            n->letters = std::string(1, c);
        }
        return n;
    }
};

std::set<size_t> ends(const Node& n, const std::string& w, const std::set<size_t>& from) {
    std::set<size_t> out;
    switch (n.kind) {
    case 'c':
        for (size_t p : from)
            if (p < w.size() && n.letters.find(w[p]) != std::string::npos) out.insert(p + 1);
        return out;
    case '.': {
        std::set<size_t> cur = from;
        for (const auto& k : n.kids) cur = ends(*k, w, cur);
        return cur;
    }
    case '|':
        for (const auto& k : n.kids)
            for (size_t p : ends(*k, w, from)) out.insert(p);
        return out;
    default: {  // '*', '+', '?'
        std::set<size_t> reached = n.kind == '+' ? std::set<size_t>() : from;
        std::set<size_t> frontier = from;
        for (int round = 0; !frontier.empty(); ++round) {
            std::set<size_t> next;
            for (size_t p : ends(*n.kids[0], w, frontier))
                if (reached.insert(p).second || (n.kind == '+' && round == 0)) next.insert(p);
            if (n.kind == '?') break;
            frontier = next;
        }
        return reached;
    }
    }
}

bool oracleMatches(const std::string& expr, const std::string& w) {
    OracleParser p{expr};
    const std::unique_ptr<Node> tree = p.alt();
    return ends(*tree, w, {0}).count(w.size()) > 0;
}

// Every string over `letters` of length 0 .. maxLen.
std::vector<std::string> allStrings(const std::string& letters, size_t maxLen) {
    std::vector<std::string> out = {""};
    for (size_t i = 0; i < out.size(); ++i)
        if (out[i].size() < maxLen)
            for (char c : letters) out.push_back(out[i] + c);
    return out;
}

VertexType typeOfLetter(char c) { return VertexType(std::string("LDGSE").find(c)); }

PathExpression::State forwardState(const PathExpression& e, const std::string& u) {
    PathExpression::State q = e.start();
    for (char c : u) q = e.step(q, typeOfLetter(c));
    return q;
}
PathExpression::State backwardState(const PathExpression& e, const std::string& v) {  // reads v from its end
    PathExpression::State b = e.backStart();
    for (size_t i = v.size(); i-- > 0;) b = e.backStep(b, typeOfLetter(v[i]));
    return b;
}

const char* kExpressions[] = {"L.*E",       "LE",           "LDE",           "LD+E",          "LD+DE",
                              "LS+DE",      "L(D|S)*E",     "L[DG]S*E",      "L[DG]S*E|LS*E", "L.*S.*E",
                              "L[^S]*E",    "LS*(D|G)?S*E", "L(DS|SD)*E",    "L((D|G)S)+E",   "L D G? S* E",
                              "L(S*D)*E",   "L.?.?E",       "LS+[DG]S*E",    "L(D|)E",        ".*",
                              "L(G|S)+D*E", "L[DS][DS]E",   "L(D*|S*)(G)?E", "LSDS*E|LDSE"};

}  // namespace

TEST_CASE("paths: the automaton accepts exactly what an independent matcher accepts (every string up to 5 letters)") {
    const std::vector<std::string> strings = allStrings("LDGSE", 5);
    for (const char* text : kExpressions) {
        const PathExpression e(text);
        int mismatches = 0;
        for (const std::string& w : strings) {
            const bool want = oracleMatches(text, w), got = e.matches(w);
            if (want != got && ++mismatches <= 3)
                FAIL_CHECK("'" << text << "' on '" << w << "': automaton " << got << ", matcher " << want);
        }
        // Longer paths of the path alphabet: L (D|G|S)^n E up to n = 6.
        for (const std::string& mid : allStrings("DGS", 6)) {
            const std::string w = "L" + mid + "E";
            const bool want = oracleMatches(text, w), got = e.matches(w);
            if (want != got && ++mismatches <= 3)
                FAIL_CHECK("'" << text << "' on '" << w << "': automaton " << got << ", matcher " << want);
        }
        CHECK_MESSAGE(mismatches == 0, "'" << text << "': " << mismatches << " strings decided differently");
        CHECK(e.states() <= PathExpression::kMaxStates);
    }
}

TEST_CASE(
    "paths: the backward automaton reads the reversed string, and every split of a path joins exactly when it "
    "matches") {
    const std::vector<std::string> mids = allStrings("DGS", 5);
    for (const char* text : kExpressions) {
        const PathExpression e(text);
        int bad = 0;
        for (const std::string& mid : mids) {
            const std::string w = "L" + mid + "E";
            const bool want = e.matches(w);
            if (e.backAccepting(backwardState(e, w)) != want && ++bad <= 3)
                FAIL_CHECK("'" << text << "': backward automaton on '" << w << "' says " << !want);
            for (size_t cut = 0; cut <= w.size(); ++cut) {
                const std::string u = w.substr(0, cut), v = w.substr(cut);
                if (e.joins(forwardState(e, u), backwardState(e, v)) != want && ++bad <= 3)
                    FAIL_CHECK("'" << text << "': '" << u << "' joined with '" << v << "' says " << !want);
            }
        }
        CHECK_MESSAGE(bad == 0, "'" << text << "': " << bad << " wrong answers");
    }
}

TEST_CASE("paths: live states are those from which some path can still match (brute force)") {
    // A completion exists iff one exists shorter than the automaton has states.
    const std::vector<std::string> prefixes = allStrings("DGS", 4), completions = allStrings("DGS", 7);
    for (const char* text : kExpressions) {
        const PathExpression e(text);
        REQUIRE_MESSAGE(e.states() <= 8,
                        "'" << text << "': completions of up to 7 letters do not cover " << e.states() << " states");
        for (const std::string& mid : prefixes) {
            // Forward: the light prefix L mid.
            bool can = false;
            for (const std::string& rest : completions) can = can || e.matches("L" + mid + rest + "E");
            CHECK_MESSAGE(e.live(forwardState(e, "L" + mid)) == can,
                          "'" << text << "': after 'L" << mid << "' live says " << !can);
            // Backward: the eye suffix mid E.
            bool canBack = false;
            for (const std::string& rest : completions) canBack = canBack || e.matches("L" + rest + mid + "E");
            CHECK_MESSAGE(e.backLive(backwardState(e, mid + "E")) == canBack,
                          "'" << text << "': before '" << mid << "E' backLive says " << !canBack);
        }
    }
}

TEST_CASE("paths: the longest matching path and whether any path matches, per set of interior types") {
    const TypeSet D = typeBit(VertexType::D), G = typeBit(VertexType::G), S = typeBit(VertexType::S);
    const PathExpression lde("LDE"), caustic("LS+DE"), direct("L[DG]S*E"), bounded("L.?.?E");
    CHECK(lde.longestInterior() == 1);
    CHECK(bounded.longestInterior() == 2);
    CHECK(caustic.longestInterior() == PathExpression::kUnbounded);
    CHECK(caustic.longestInterior(TypeSet(D | S)) == PathExpression::kUnbounded);
    CHECK(direct.longestInterior(D) == 1);  // without S the chain S* is empty
    CHECK(caustic.matchesSome(TypeSet(D | S)));
    CHECK_FALSE(caustic.matchesSome(TypeSet(D | G)));     // no mirror or glass: no caustic
    CHECK_FALSE(caustic.matchesSome(TypeSet(D | S), 1));  // a caustic needs two interior vertices
    CHECK(caustic.matchesSome(TypeSet(D | S), 2));
    CHECK_FALSE(lde.matchesSome(G));
    // Brute force for every expression and every set of interior types.
    for (const char* text : kExpressions) {
        const PathExpression e(text);
        for (TypeSet types = 0; types < 8; ++types) {
            const TypeSet set = TypeSet((types & 1 ? D : 0) | (types & 2 ? G : 0) | (types & 4 ? S : 0));
            std::string letters;
            for (char c : std::string("DGS"))
                if (set & typeBit(typeOfLetter(c))) letters += c;
            int longest = -2;
            bool beyond = false;
            // A bounded expression here matches at most 3 interior vertices; an unbounded one (its
            // loops have periods 1 or 2) matches some n in 5 .. 8.
            for (const std::string& mid : allStrings(letters, 8))
                if (e.matches("L" + mid + "E")) {
                    if (mid.size() > 4) beyond = true;
                    else longest = std::max(longest, int(mid.size()));
                }
            CHECK_MESSAGE(e.matchesSome(set) == (longest >= 0 || beyond), "'" << text << "' types " << letters);
            if (longest >= 0 || beyond) {
                const int want = beyond ? PathExpression::kUnbounded : longest;
                CHECK_MESSAGE(e.longestInterior(set) == want, "'" << text << "' types " << letters);
            }
        }
    }
}

TEST_CASE("paths: a malformed expression names its problem and points at the character") {
    struct Case {
        const char* text;
        size_t column;
        const char* says;
    };
    const Case cases[] = {
        {"L(D|S*E", 1, "never closed"},
        {"LD)E", 2, "')' without a '('"},
        {"*LDE", 0, "repeats nothing"},
        {"L|*E", 2, "repeats nothing"},
        {"LdE", 1, "upper case ('D')"},
        {"LXE", 1, "'X' is not a vertex type"},
        {"L[DS", 1, "'[' is never closed"},
        {"L[]E", 1, "matches no vertex type"},
        {"L[^LDGSE]E", 1, "matches no vertex type"},
        {"L[DQ]E", 3, "'Q' is not a vertex type inside [...]"},
        {"", 0, "empty expression"},
        {"   ", 0, "empty expression"},
        {"L D ) E", 4, "')' without"},
    };
    for (const Case& c : cases) {
        CAPTURE(c.text);
        bool threw = false;
        try {
            PathExpression e(c.text);
        } catch (const PathExpressionError& err) {
            threw = true;
            CHECK(err.column == c.column);
            CHECK_MESSAGE(err.problem.find(c.says) != std::string::npos, err.problem);
            const std::string pointed = err.pointed("  ");
            CHECK_MESSAGE(pointed.find("\n  " + std::string(c.text) + "\n  " + std::string(c.column, ' ') + "^") !=
                              std::string::npos,
                          pointed);
        }
        CHECK_MESSAGE(threw, "'" << c.text << "' was accepted");
    }
    // Well formed, but no path L (D|G|S)* E matches: refused too, without a caret.
    for (const char* text : {"LD*", "DE", "LEDE", "E.*L"}) {
        bool threw = false;
        try {
            PathExpression e(text);
        } catch (const PathExpressionError& err) {
            threw = true;
            CHECK(err.column == std::string::npos);
            CHECK_MESSAGE(err.problem.find("matches no path") != std::string::npos, err.problem);
        }
        CHECK_MESSAGE(threw, "'" << text << "' matches no path but was accepted");
    }
}

TEST_CASE("paths: the automata are small (minimised) and every path is L.*E") {
    CHECK(PathExpression("L.*E").states() == 4);  // start, after L (and .*), accepting, dead
    CHECK(PathExpression("L(D|G|S)*E").states() == PathExpression("L.*E").states());
    const PathExpression all("L.*E");
    for (const std::string& mid : allStrings("DGS", 6)) CHECK(all.matches("L" + mid + "E"));
}
