// Hostile: constant expressions that keep the compiler busy for days. Each Spin<K> is its own
// evaluation of 4·10^6 loop steps (under GCC's limit of 2^25 operations per evaluation, so it
// succeeds, in about a second), and the static_assert asks for a million of them: the build
// must time out, not the grader.
#include <utility>

template <unsigned long K>
constexpr unsigned long spin() {
    unsigned long s = K;
    for (unsigned long i = 0; i < 2000; ++i)
        for (unsigned long j = 0; j < 2000; ++j) s += i ^ j;
    return s;
}
template <unsigned long K>
struct Spin {
    static constexpr unsigned long value = spin<K>();
};
template <unsigned long... K>
constexpr unsigned long sum(std::integer_sequence<unsigned long, K...>) {
    return (Spin<K>::value + ...);
}
static_assert(sum(std::make_integer_sequence<unsigned long, 1000000>{}) != 1, "never reached in time");
