// Hostile: constant expressions that keep the compiler busy for days. Each leaf of the tree is its
// own evaluation of 2.5·10^5 loop steps (under GCC's limit of 2^25 operations per evaluation and
// clang's of 2^20 steps, so it succeeds under both, in a fraction of a second), and every node is
// a constant of its own; a binary tree of a million leaves (20 levels: under both compilers'
// template depth and nesting limits) asks for all of them: the build must time out, not the grader.
template <unsigned long K>
constexpr unsigned long spin() {
    unsigned long s = K;
    for (unsigned long i = 0; i < 500; ++i)
        for (unsigned long j = 0; j < 500; ++j) s += i ^ j;
    return s;
}
template <unsigned long Lo, unsigned long Hi>
struct Tree;
template <unsigned long Lo, unsigned long Hi>
constexpr unsigned long node() {
    if constexpr (Hi - Lo == 1) return spin<Lo>();
    else return Tree<Lo, (Lo + Hi) / 2>::value + Tree<(Lo + Hi) / 2, Hi>::value;
}
template <unsigned long Lo, unsigned long Hi>
struct Tree {
    static constexpr unsigned long value = node<Lo, Hi>();
};
static_assert(Tree<0, 1000000>::value != 1, "never reached in time");
