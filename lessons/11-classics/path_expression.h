// Heckbert's path expressions (Heckbert 1990; lesson 11, Eq. 11.1-11.5): regular expressions
// over the types of a path's vertices, written from the light to the eye, compiled to a small
// deterministic automaton (DFA) that an integrator steps one vertex at a time. `pathspace render
// --paths EXPR` renders only the paths the expression matches (lesson 11's plumbing applies it in
// pt, lt, bpt and pm).
//
// The alphabet (Eq. 11.1): L the vertex on a light (x_0: an area light, a point light or the
// background), E the eye (the camera, x_k), and for every vertex in between its BSDF: D
// Lambertian, G glossy (non-delta and non-Lambertian: Phong), S specular (a delta BSDF: mirror,
// glass). Heckbert's paper has only D and S; we split the non-delta BSDFs into D and G. Every path
// is L (D|G|S)* E, which `L.*E` also says.
//
// The syntax: a type letter; `.` any type; a class `[DS]` (one of), `[^S]` (any but); `(...)`;
// postfix `*` (zero or more), `+` (one or more), `?` (zero or one); concatenation; `|` (either).
// Spaces are ignored. No <regex>: the project avoids it for compile time; the automaton is ours.
//
// Two automata (Eq. 11.3, 11.4): the forward DFA reads a path from the light (L first), as a
// light walk builds it; the backward one reads it from the eye (E first), as a camera walk builds
// it. A backward state is the SET of forward states from which the suffix read so far is
// accepted, so a light prefix u (forward state q) and an eye suffix v (backward state b) make a
// matching path u v exactly when q is in b's set (joins, Eq. 11.5): bidirectional methods test a
// connection in O(1). A state from which no path can be completed is dead (`live` false): a
// walk can stop there (Eq. 11.6).
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace ps {

// Heckbert's vertex types (Eq. 11.1).
enum class VertexType : uint8_t { L, D, G, S, E };
constexpr int kVertexTypes = 5;
// 'L', 'D', 'G', 'S', 'E'.
char typeLetter(VertexType t);

// A set of vertex types, bit int(t) for type t (e.g. the interior types a scene's surfaces have).
using TypeSet = uint8_t;
constexpr TypeSet typeBit(VertexType t) { return TypeSet(1u << unsigned(t)); }
constexpr TypeSet kInteriorTypes = TypeSet(typeBit(VertexType::D) | typeBit(VertexType::G) | typeBit(VertexType::S));

// A malformed expression: what is wrong and where.
class PathExpressionError : public std::runtime_error {
public:
    PathExpressionError(const std::string& expression, size_t column, const std::string& problem);
    std::string expression, problem;
    size_t column;  // of the offending character (0-based; expression.size(): its end); npos: none
    // The problem, then the expression on the next line and a caret under the offending character:
    //   the '(' is never closed
    //     L(D|S*E
    //      ^
    // (only the problem when the error holds neither expression nor column: one too long to show)
    std::string pointed(const std::string& indent = "  ") const;
};

class PathExpression {
public:
    using State = uint8_t;
    // A state fits in a byte (lesson 11's photons keep theirs in one).
    static constexpr int kMaxStates = 255;
    // Refused before any work: a longer expression, or groups nested deeper (the parser recurses
    // once per level). Heckbert's expressions are a few dozen characters.
    static constexpr size_t kMaxLength = 1000;
    static constexpr int kMaxNesting = 64;

    // Compiles text; throws PathExpressionError for a malformed expression, for one that matches
    // no path L (D|G|S)* E at all, for one longer than kMaxLength or nested deeper than
    // kMaxNesting, and for one whose automata need more than kMaxStates states (or whose
    // construction would take more than a bounded amount of work on the way).
    explicit PathExpression(const std::string& text);
    const std::string& text() const { return text_; }

    // The forward DFA (light to eye, Eq. 11.3). Complete: every state has a successor for every
    // type (a dead state takes what cannot match).
    State start() const { return 0; }
    State step(State q, VertexType t) const { return fwd_[q].next[int(t)]; }
    bool accepting(State q) const { return fwd_[q].accepting; }
    // Some (D|G|S)* E leads from q to an accepting state: the path read so far can still match.
    bool live(State q) const { return fwd_[q].live; }
    int states() const { return int(fwd_.size()); }

    // The backward DFA (eye to light, Eq. 11.4): reads E first and L last.
    State backStart() const { return 0; }
    State backStep(State b, VertexType t) const { return back_[b].next[int(t)]; }
    // The reversed string read so far is in the language.
    bool backAccepting(State b) const { return back_[b].set[start()]; }
    // Some L (D|G|S)* read after it makes a match: the camera walk can still find a matching path.
    bool backLive(State b) const { return back_[b].live; }
    int backStates() const { return int(back_.size()); }

    // The light prefix u (read forward into q) and the eye suffix v (read backward into b) form a
    // path u v that matches (Eq. 11.5).
    bool joins(State q, State b) const { return back_[b].set[q]; }

    // Whether the whole path matches (x_0 first).
    bool matches(const std::vector<VertexType>& path) const;
    // The same for letters, e.g. "LDSE"; false if a character is not one of L, D, G, S, E.
    bool matches(const std::string& letters) const;

    // Some path L t_1 .. t_n E with every t_i in `types` and n <= maxInterior (-1: any n) matches.
    bool matchesSome(TypeSet types = kInteriorTypes, int maxInterior = -1) const;
    // The largest n of a matching path L t_1 .. t_n E with every t_i in `types`; kUnbounded if
    // there is no largest. Meaningful when matchesSome(types).
    static constexpr int kUnbounded = -1;
    int longestInterior(TypeSet types = kInteriorTypes) const;

private:
    struct Forward {
        State next[kVertexTypes] = {};
        bool accepting = false, live = false;
    };
    struct Backward {
        State next[kVertexTypes] = {};
        std::vector<bool> set;  // over the forward states
        bool live = false;
    };
    std::string text_;
    std::vector<Forward> fwd_;
    std::vector<Backward> back_;
};

}  // namespace ps
