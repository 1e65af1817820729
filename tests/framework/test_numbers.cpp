// Tests of framework/numbers.h: whole-string number parsing. The strtod road (used where the
// standard library has no floating-point std::from_chars, e.g. AppleClang's libc++) must accept
// and reject exactly what std::from_chars does on the scene files' and command lines' tokens.
#include <doctest/doctest.h>
#include <charconv>
#include <string>
#include "numbers.h"

using namespace ps;

TEST_CASE("numbers: the strtod road agrees with std::from_chars, float and double") {
    const char* tokens[] = {"0",     "1",        "-1",     "1.5",  "-0.25", ".5",    "5.",   "1e3",
                            "1E-3",  "-2.5e+2",  "3.4e38", "1e39", "-1e39", "1e309", "inf",  "-inf",
                            "nan",   "infinity", "",       "-",    "+1",    " 1",    "1 ",   "1.5cm",
                            "1.2.3", "0x10",     "-0x1p3", "e5",   "1e",    "--1",   "many", "1,5"};
    for (const char* t : tokens) {
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
