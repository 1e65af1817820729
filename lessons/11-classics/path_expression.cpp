// Heckbert's path expressions: the parser, Thompson's NFA, the subset construction, Moore's
// minimisation, and the backward automaton of sets (lesson 11, Eq. 11.3-11.6). See
// path_expression.h.
#include "11-classics/path_expression.h"
#include <algorithm>
#include <map>

namespace ps {

char typeLetter(VertexType t) { return "LDGSE"[int(t)]; }

namespace {

// The letter's type, or -1.
int typeOf(char c) {
    switch (c) {
    case 'L': return int(VertexType::L);
    case 'D': return int(VertexType::D);
    case 'G': return int(VertexType::G);
    case 'S': return int(VertexType::S);
    case 'E': return int(VertexType::E);
    default: return -1;
    }
}

constexpr TypeSet kAllTypes = TypeSet((1u << kVertexTypes) - 1u);

// Thompson's NFA: every state has epsilon edges and at most one edge on a set of types.
struct Nfa {
    struct State {
        std::vector<int> eps;
        TypeSet on = 0;  // the types of the one labelled edge (0: none)
        int to = -1;
    };
    std::vector<State> states;
    int add() {
        states.emplace_back();
        return int(states.size()) - 1;
    }
};

struct Fragment {
    int in = -1, out = -1;
};

// Recursive descent over   alt := concat ('|' concat)*,  concat := repeat*,
// repeat := atom ('*' | '+' | '?')*,  atom := type | '.' | '[' '^'? types ']' | '(' alt ')'.
class Parser {
public:
    Parser(const std::string& text, Nfa& nfa) : text_(text), nfa_(nfa) {}

    Fragment parse() {
        skipSpaces();
        if (pos_ == text_.size()) fail(0, "an empty expression matches no path");
        const Fragment f = alternatives();
        if (pos_ < text_.size()) fail(pos_, "')' without a '(' before it");  // the only way to stop early
        return f;
    }

private:
    [[noreturn]] void fail(size_t column, const std::string& problem) const {
        throw PathExpressionError(text_, column, problem);
    }
    void skipSpaces() {
        while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t')) ++pos_;
    }
    bool atEnd() {
        skipSpaces();
        return pos_ == text_.size();
    }

    Fragment epsilon() {
        const Fragment f{nfa_.add(), nfa_.add()};
        nfa_.states[size_t(f.in)].eps.push_back(f.out);
        return f;
    }
    Fragment symbols(TypeSet on) {
        const Fragment f{nfa_.add(), nfa_.add()};
        nfa_.states[size_t(f.in)].on = on;
        nfa_.states[size_t(f.in)].to = f.out;
        return f;
    }
    Fragment concat(Fragment a, Fragment b) {
        nfa_.states[size_t(a.out)].eps.push_back(b.in);
        return {a.in, b.out};
    }

    Fragment alternatives() {
        Fragment f = sequence();
        while (!atEnd() && text_[pos_] == '|') {
            ++pos_;
            const Fragment g = sequence();
            const Fragment both{nfa_.add(), nfa_.add()};
            nfa_.states[size_t(both.in)].eps = {f.in, g.in};
            nfa_.states[size_t(f.out)].eps.push_back(both.out);
            nfa_.states[size_t(g.out)].eps.push_back(both.out);
            f = both;
        }
        return f;
    }

    Fragment sequence() {
        Fragment f = epsilon();
        while (!atEnd() && text_[pos_] != '|' && text_[pos_] != ')') f = concat(f, repeated());
        return f;
    }

    Fragment repeated() {
        Fragment f = atom();
        while (!atEnd() && (text_[pos_] == '*' || text_[pos_] == '+' || text_[pos_] == '?')) {
            const char op = text_[pos_++];
            const Fragment r{nfa_.add(), nfa_.add()};
            nfa_.states[size_t(r.in)].eps.push_back(f.in);
            nfa_.states[size_t(f.out)].eps.push_back(r.out);
            if (op != '+') nfa_.states[size_t(r.in)].eps.push_back(r.out);  // zero times
            if (op != '?') nfa_.states[size_t(f.out)].eps.push_back(f.in);  // again
            f = r;
        }
        return f;
    }

    Fragment atom() {
        const size_t at = pos_;
        const char c = text_[pos_];
        if (typeOf(c) >= 0) {
            ++pos_;
            return symbols(typeBit(VertexType(typeOf(c))));
        }
        switch (c) {
        case '.': ++pos_; return symbols(kAllTypes);
        case '[': return typeClass();
        case '(': {
            ++pos_;
            const Fragment f = alternatives();
            if (atEnd()) fail(at, "this '(' is never closed");
            ++pos_;  // ')': alternatives() stops only there or at the end
            return f;
        }
        case '*':
        case '+':
        case '?': fail(at, std::string("'") + c + "' repeats nothing (write it after a type, a class or a group)");
        default: break;
        }
        unknown(at);
    }

    Fragment typeClass() {
        const size_t open = pos_++;
        bool negate = false;
        TypeSet on = 0;
        skipSpaces();
        if (pos_ < text_.size() && text_[pos_] == '^') {
            negate = true;
            ++pos_;
        }
        for (;;) {
            skipSpaces();
            if (pos_ == text_.size()) fail(open, "this '[' is never closed");
            const char c = text_[pos_];
            if (c == ']') break;
            if (typeOf(c) < 0) unknown(pos_, " inside [...]");
            on = TypeSet(on | typeBit(VertexType(typeOf(c))));
            ++pos_;
        }
        ++pos_;  // ']'
        if (negate) on = TypeSet(kAllTypes & ~on);
        if (on == 0) fail(open, "this class matches no vertex type");
        return symbols(on);
    }

    [[noreturn]] void unknown(size_t at, const std::string& where = "") const {
        const char c = text_[at];
        std::string problem =
            "'" + std::string(1, c) + "' is not a vertex type" + where +
            " (types: L light, E eye, D diffuse, G glossy, S specular; operators: | * + ? . ( ) [ ] ^)";
        if (typeOf(char(c - 'a' + 'A')) >= 0 && c >= 'a' && c <= 'z')
            problem = "'" + std::string(1, c) + "' is not a vertex type" + where + ": the types are upper case ('" +
                      std::string(1, char(c - 'a' + 'A')) + "')";
        fail(at, problem);
    }

    const std::string& text_;
    Nfa& nfa_;
    size_t pos_ = 0;
};

using StateSet = std::vector<int>;  // sorted NFA states

// `work` counts the states and edges visited (the construction's budget, kMaxWork).
StateSet closure(const Nfa& nfa, StateSet set, size_t& work) {
    std::vector<bool> in(nfa.states.size(), false);
    for (int s : set) in[size_t(s)] = true;
    for (size_t i = 0; i < set.size(); ++i) {
        work += 1 + nfa.states[size_t(set[i])].eps.size();
        for (int e : nfa.states[size_t(set[i])].eps)
            if (!in[size_t(e)]) {
                in[size_t(e)] = true;
                set.push_back(e);
            }
    }
    std::sort(set.begin(), set.end());
    return set;
}

// The construction's budget: NFA states and edges visited by the subset construction, plus
// states times rounds of the minimisation. An expression of kMaxLength characters builds an NFA
// of up to a few thousand states, and its DFA, capped at 4096 states before minimising, could
// take 10^8 such steps; the budget stops it at about 0.3 s ('L' then '.?' 490 times: the DFA has
// 490 states, each a closure over most of the NFA). Expressions of a lesson take a few hundred.
constexpr size_t kMaxWork = size_t(1) << 24;

// Refused before parsing: too long, or groups nested too deep (one line, no expression shown).
void checkSize(const std::string& text) {
    if (text.size() > PathExpression::kMaxLength)
        throw PathExpressionError("", std::string::npos,
                                  "the expression is " + std::to_string(text.size()) + " characters long; at most " +
                                      std::to_string(PathExpression::kMaxLength) + " are accepted");
    int depth = 0;
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] == ')') depth = std::max(0, depth - 1);
        if (text[i] == '(' && ++depth > PathExpression::kMaxNesting)
            throw PathExpressionError("", std::string::npos,
                                      "groups nested more than " + std::to_string(PathExpression::kMaxNesting) +
                                          " deep (the '(' at character " + std::to_string(i + 1) + ")");
    }
}

}  // namespace

PathExpressionError::PathExpressionError(const std::string& expression_, size_t column_, const std::string& problem_)
    : std::runtime_error(problem_ + (column_ == std::string::npos ? std::string()
                                                                  : " (character " + std::to_string(column_ + 1) +
                                                                        " of '" + expression_ + "')")),
      expression(expression_),
      problem(problem_),
      column(column_) {}

std::string PathExpressionError::pointed(const std::string& indent) const {
    if (expression.empty() && column == std::string::npos) return problem;
    std::string s = problem + "\n" + indent + expression;
    if (column != std::string::npos) s += "\n" + indent + std::string(column, ' ') + "^";
    return s;
}

PathExpression::PathExpression(const std::string& text) : text_(text) {
    // 1. Thompson's NFA.
    checkSize(text);
    Nfa nfa;
    const Fragment whole = Parser(text, nfa).parse();
    const auto tooComplex = [&]() {
        throw PathExpressionError(
            text, std::string::npos,
            "the expression needs more than " + std::to_string(kMaxStates) + " automaton states: write it more simply");
    };
    size_t work = 0;
    const auto spend = [&](size_t units) {
        work += units;
        if (work > kMaxWork)
            throw PathExpressionError(text, std::string::npos,
                                      "building the expression's automaton takes more than " +
                                          std::to_string(kMaxWork) + " steps: write it more simply");
    };

    // 2. The subset construction (Eq. 11.3): a DFA state is the set of NFA states the NFA can be
    //    in; the empty set is the dead state.
    std::map<StateSet, int> index;
    std::vector<StateSet> sets;
    std::vector<std::vector<int>> next;
    const auto find = [&](const StateSet& s) {
        auto it = index.find(s);
        if (it != index.end()) return it->second;
        if (sets.size() >= 4096) tooComplex();
        index.emplace(s, int(sets.size()));
        sets.push_back(s);
        next.emplace_back(kVertexTypes, -1);
        return int(sets.size()) - 1;
    };
    find(closure(nfa, {whole.in}, work));
    for (size_t d = 0; d < sets.size(); ++d)
        for (int t = 0; t < kVertexTypes; ++t) {
            StateSet moved;
            for (int s : sets[d]) {
                const Nfa::State& ns = nfa.states[size_t(s)];
                if (ns.to >= 0 && (ns.on & (1u << unsigned(t)))) moved.push_back(ns.to);
            }
            size_t used = sets[d].size();
            next[d][size_t(t)] = find(closure(nfa, moved, used));
            spend(used);
        }
    const size_t n = sets.size();
    std::vector<bool> accepting(n);
    for (size_t d = 0; d < n; ++d) accepting[d] = std::binary_search(sets[d].begin(), sets[d].end(), whole.out);

    // 3. Moore's minimisation: split the states by acceptance, then by the classes of their
    //    successors, until nothing splits; equivalent states merge.
    std::vector<int> cls(n);
    for (size_t d = 0; d < n; ++d) cls[d] = accepting[d] ? 1 : 0;
    for (size_t classes = 0;;) {
        spend(n * (kVertexTypes + 1));
        std::map<std::vector<int>, int> signature;
        std::vector<int> refined(n);
        for (size_t d = 0; d < n; ++d) {
            std::vector<int> sig = {cls[d]};
            for (int t = 0; t < kVertexTypes; ++t) sig.push_back(cls[size_t(next[d][size_t(t)])]);
            refined[d] = signature.emplace(sig, int(signature.size())).first->second;
        }
        cls = refined;
        if (signature.size() == classes) break;
        classes = signature.size();
    }
    // Number the classes in breadth-first order from the start, so the start is state 0.
    std::vector<int> order(n, -1), representative;
    std::vector<int> queue = {cls[0]};
    std::vector<int> number(n, -1);
    number[size_t(cls[0])] = 0;
    representative.push_back(0);
    for (size_t i = 0; i < queue.size(); ++i) {
        const int c = queue[i];
        size_t d = 0;
        while (cls[d] != c) ++d;
        representative[size_t(number[size_t(c)])] = int(d);
        for (int t = 0; t < kVertexTypes; ++t) {
            const int c2 = cls[size_t(next[d][size_t(t)])];
            if (number[size_t(c2)] < 0) {
                number[size_t(c2)] = int(queue.size());
                queue.push_back(c2);
                representative.push_back(0);
            }
        }
    }
    if (queue.size() > size_t(kMaxStates)) tooComplex();
    fwd_.resize(queue.size());
    for (size_t q = 0; q < fwd_.size(); ++q) {
        const size_t d = size_t(representative[q]);
        fwd_[q].accepting = accepting[d];
        for (int t = 0; t < kVertexTypes; ++t) fwd_[q].next[t] = State(number[size_t(cls[size_t(next[d][size_t(t)])])]);
    }

    // 4. Live states (Eq. 11.6): from q some (D|G|S)* E reaches an accepting state.
    for (Forward& f : fwd_) f.live = fwd_[f.next[int(VertexType::E)]].accepting;
    for (bool changed = true; changed;) {
        changed = false;
        for (Forward& f : fwd_)
            for (VertexType t : {VertexType::D, VertexType::G, VertexType::S})
                if (!f.live && fwd_[f.next[int(t)]].live) f.live = changed = true;
    }

    // 5. The backward automaton (Eq. 11.4): a state is the set of forward states from which the
    //    suffix read so far (backwards) is accepted; reading t before it keeps the p with
    //    step(p, t) in the set.
    const size_t m = fwd_.size();
    std::map<std::vector<bool>, int> backIndex;
    const auto findBack = [&](const std::vector<bool>& set) {
        auto it = backIndex.find(set);
        if (it != backIndex.end()) return it->second;
        if (back_.size() >= size_t(kMaxStates)) tooComplex();
        backIndex.emplace(set, int(back_.size()));
        back_.emplace_back();
        back_.back().set = set;
        return int(back_.size()) - 1;
    };
    std::vector<bool> acceptingSet(m);
    for (size_t q = 0; q < m; ++q) acceptingSet[q] = fwd_[q].accepting;
    findBack(acceptingSet);
    for (size_t b = 0; b < back_.size(); ++b)
        for (int t = 0; t < kVertexTypes; ++t) {
            std::vector<bool> before(m);
            for (size_t q = 0; q < m; ++q) before[q] = back_[b].set[fwd_[q].next[t]];
            const int c = findBack(before);
            back_[b].next[t] = State(c);
        }
    // Backward live: the set meets the forward states some L (D|G|S)* reaches from the start.
    std::vector<bool> reach(m, false);
    std::vector<State> stack = {step(start(), VertexType::L)};
    reach[stack[0]] = true;
    while (!stack.empty()) {
        const State q = stack.back();
        stack.pop_back();
        for (VertexType t : {VertexType::D, VertexType::G, VertexType::S}) {
            const State r = step(q, t);
            if (!reach[r]) {
                reach[r] = true;
                stack.push_back(r);
            }
        }
    }
    for (Backward& b : back_)
        for (size_t q = 0; q < m && !b.live; ++q) b.live = b.set[q] && reach[q];

    if (!matchesSome())
        throw PathExpressionError(text, std::string::npos,
                                  "'" + text +
                                      "' matches no path: every path is L(D|G|S)*E, from the light (L) "
                                      "to the eye (E)");
}

bool PathExpression::matches(const std::vector<VertexType>& path) const {
    State q = start();
    for (VertexType t : path) q = step(q, t);
    return accepting(q);
}

bool PathExpression::matches(const std::string& letters) const {
    std::vector<VertexType> path;
    for (char c : letters) {
        const int t = typeOf(c);
        if (t < 0) return false;
        path.push_back(VertexType(t));
    }
    return matches(path);
}

bool PathExpression::matchesSome(TypeSet types, int maxInterior) const {
    std::vector<bool> seen(fwd_.size(), false);
    std::vector<State> level = {step(start(), VertexType::L)};
    seen[level[0]] = true;
    for (int n = 0; !level.empty(); ++n) {
        for (State q : level)
            if (accepting(step(q, VertexType::E))) return true;
        if (maxInterior >= 0 && n == maxInterior) return false;
        std::vector<State> nextLevel;
        for (State q : level)
            for (VertexType t : {VertexType::D, VertexType::G, VertexType::S})
                if ((types & typeBit(t)) && !seen[step(q, t)]) {
                    seen[step(q, t)] = true;
                    nextLevel.push_back(step(q, t));
                }
        level = nextLevel;
    }
    return false;
}

int PathExpression::longestInterior(TypeSet types) const {
    const size_t m = fwd_.size();
    const VertexType interior[] = {VertexType::D, VertexType::G, VertexType::S};
    // Useful states: some path over `types` then E reaches acceptance.
    std::vector<bool> useful(m);
    for (size_t q = 0; q < m; ++q) useful[q] = accepting(step(State(q), VertexType::E));
    for (bool changed = true; changed;) {
        changed = false;
        for (size_t q = 0; q < m; ++q)
            for (VertexType t : interior)
                if ((types & typeBit(t)) && !useful[q] && useful[step(State(q), t)]) useful[q] = changed = true;
    }
    // Longest path by depth-first search over the useful states reachable after L; a state met
    // again on the current branch is a cycle: no bound.
    std::vector<int> longest(m, -2), mark(m, 0);  // mark: 0 unvisited, 1 on the branch, 2 done
    bool cycle = false;
    const auto visit = [&](auto&& self, State q) -> int {
        if (mark[q] == 1) {
            cycle = true;
            return 0;
        }
        if (mark[q] == 2) return longest[q];
        mark[q] = 1;
        int best = accepting(step(q, VertexType::E)) ? 0 : -2;
        for (VertexType t : interior)
            if ((types & typeBit(t)) && useful[step(q, t)]) best = std::max(best, 1 + self(self, step(q, t)));
        mark[q] = 2;
        return longest[q] = best;
    };
    const State first = step(start(), VertexType::L);
    if (!useful[first]) return kUnbounded;
    const int n = visit(visit, first);
    return cycle ? kUnbounded : n;
}

}  // namespace ps
