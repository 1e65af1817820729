// Tests of framework/numbers.h: whole-string number parsing. The strtod road (used where the
// standard library has no floating-point std::from_chars, e.g. AppleClang's libc++) must accept
// and reject exactly what std::from_chars does on the scene files' and command lines' tokens.
#include <doctest/doctest.h>
#include <charconv>
#include <cmath>
#include <iterator>
#include <string>
#include "numbers.h"

using namespace ps;

namespace {

const char* const kTokens[] = {"0",     "1",        "-1",     "1.5",  "-0.25", ".5",    "5.",   "1e3",
                               "1E-3",  "-2.5e+2",  "3.4e38", "1e39", "-1e39", "1e309", "inf",  "-inf",
                               "nan",   "infinity", "",       "-",    "+1",    " 1",    "1 ",   "1.5cm",
                               "1.2.3", "0x10",     "-0x1p3", "e5",   "1e",    "--1",   "many", "1,5"};

}  // namespace

// What std::from_chars says on each token, written out: the strtod road must agree wherever the
// library has no floating-point from_chars to compare with (libc++ before LLVM 20).
TEST_CASE("numbers: the strtod road accepts and rejects the tokens as std::from_chars does") {
    const std::errc ok = std::errc(), bad = std::errc::invalid_argument, range = std::errc::result_out_of_range;
    const double inf = HUGE_VAL;
    struct Want {
        std::errc f, d;
        double value;  // when accepted (NaN: a NaN)
    };
    const Want want[] = {{ok, ok, 0.0},    {ok, ok, 1.0},     {ok, ok, -1.0},     {ok, ok, 1.5},       {ok, ok, -0.25},
                         {ok, ok, 0.5},    {ok, ok, 5.0},     {ok, ok, 1e3},      {ok, ok, 1e-3},      {ok, ok, -250.0},
                         {ok, ok, 3.4e38}, {range, ok, 1e39}, {range, ok, -1e39}, {range, range, 0.0}, {ok, ok, inf},
                         {ok, ok, -inf},   {ok, ok, NAN},     {ok, ok, inf},      {bad, bad, 0.0},     {bad, bad, 0.0},
                         {bad, bad, 0.0},  {bad, bad, 0.0},   {bad, bad, 0.0},    {bad, bad, 0.0},     {bad, bad, 0.0},
                         {bad, bad, 0.0},  {bad, bad, 0.0},   {bad, bad, 0.0},    {bad, bad, 0.0},     {bad, bad, 0.0},
                         {bad, bad, 0.0},  {bad, bad, 0.0}};
    static_assert(std::size(want) == std::size(kTokens), "one expectation per token");
    for (size_t k = 0; k < std::size(kTokens); ++k) {
        const std::string s = kTokens[k];
        float f = 7.0f;
        double d = 7.0;
        const std::errc gotF = parseFloatWithStrtod(s, f), gotD = parseFloatWithStrtod(s, d);
        CHECK_MESSAGE(int(gotF) == int(want[k].f),
                      "float '" << s << "': expected " << int(want[k].f) << ", got " << int(gotF) << " (0 = ok)");
        CHECK_MESSAGE(int(gotD) == int(want[k].d),
                      "double '" << s << "': expected " << int(want[k].d) << ", got " << int(gotD) << " (0 = ok)");
        const double v = want[k].value;
        if (gotF == ok && want[k].f == ok)
            CHECK_MESSAGE((std::isnan(v) ? std::isnan(f) : f == float(v)), "float '" << s << "': got " << f);
        else CHECK_MESSAGE(f == 7.0f, "float '" << s << "': rejected, but the value changed to " << f);
        if (gotD == ok && want[k].d == ok)
            CHECK_MESSAGE((std::isnan(v) ? std::isnan(d) : d == v), "double '" << s << "': got " << d);
        else CHECK_MESSAGE(d == 7.0, "double '" << s << "': rejected, but the value changed to " << d);
    }
}

#if defined(__cpp_lib_to_chars)  // libstdc++ 11 on; libc++ from LLVM 20 on
TEST_CASE("numbers: the strtod road agrees with std::from_chars, float and double") {
    for (const char* t : kTokens) {
        const std::string s = t;
        float f1 = 7.0f, f2 = 7.0f;
        double d1 = 7.0, d2 = 7.0;
        const std::errc want = [&] {
            auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), f1);
            return ec == std::errc() && end != s.data() + s.size() ? std::errc::invalid_argument : ec;
        }();
        const std::errc got = parseFloatWithStrtod(s, f2);
        CHECK_MESSAGE(int(got) == int(want), "float '" << s << "': from_chars says " << int(want) << ", strtod road "
                                                       << int(got) << " (0 = ok)");
        if (want == std::errc() && got == std::errc() && !std::isnan(f1))
            CHECK_MESSAGE(f1 == f2, "float '" << s << "': " << f1 << " vs " << f2);
        const std::errc wantD = [&] {
            auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), d1);
            return ec == std::errc() && end != s.data() + s.size() ? std::errc::invalid_argument : ec;
        }();
        const std::errc gotD = parseFloatWithStrtod(s, d2);
        CHECK_MESSAGE(int(gotD) == int(wantD), "double '" << s << "': from_chars says " << int(wantD)
                                                          << ", strtod road " << int(gotD) << " (0 = ok)");
        if (wantD == std::errc() && gotD == std::errc() && !std::isnan(d1))
            CHECK_MESSAGE(d1 == d2, "double '" << s << "': " << d1 << " vs " << d2);
    }
}
#endif

TEST_CASE("numbers: parseWhole takes whole integers and leaves v alone on failure") {
    int i = 5;
    CHECK(parseWhole(std::string("42"), i) == std::errc());
    CHECK(i == 42);
    CHECK(parseWhole(std::string("42x"), i) == std::errc::invalid_argument);
    CHECK(parseWhole(std::string("1.5"), i) == std::errc::invalid_argument);
    CHECK(parseWhole(std::string("99999999999"), i) == std::errc::result_out_of_range);
    CHECK(i == 42);
    float f = 1.0f;
    CHECK(parseWhole(std::string("1e39"), f) == std::errc::result_out_of_range);
    CHECK(parseWhole(std::string("2.5"), f) == std::errc());
    CHECK(f == 2.5f);
}
