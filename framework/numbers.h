// Whole-string number parsing for the scene loader and the command line: the token must be a
// number and nothing else ("1.5", "-2e3", "inf"; not " 1", "+1", "0x1p3", "1.5cm").
// std::from_chars does exactly that, but libc++ has it for float and double only from LLVM 20 on,
// so AppleClang (Xcode 16 and older) lacks it: there, and wherever the library does not announce
// it (__cpp_lib_to_chars), the same rules are applied around std::strtod in the "C" locale
// (the program never changes its locale).
#pragma once
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <system_error>
#include <type_traits>

namespace ps {

// The strtod road, compiled everywhere so that the tests can compare it with std::from_chars.
// (It differs only below the smallest normal number, where from_chars may say out of range.)
template <class T>
std::errc parseFloatWithStrtod(const std::string& s, T& v) {
    static_assert(std::is_floating_point_v<T>, "floats only");
    const size_t digits = (!s.empty() && s[0] == '-') ? 1 : 0;
    if (s.size() <= digits || std::isspace(static_cast<unsigned char>(s[digits])) || s[digits] == '+' || s[0] == '+')
        return std::errc::invalid_argument;
    if (s.size() > digits + 1 && s[digits] == '0' && (s[digits + 1] == 'x' || s[digits + 1] == 'X'))
        return std::errc::invalid_argument;  // strtod reads hexadecimal, from_chars (general) does not
    char* end = nullptr;
    errno = 0;
    // strtof for a float: rounded once, as from_chars does (strtod and then float could round twice).
    T x{};
    if constexpr (std::is_same_v<T, float>) x = std::strtof(s.c_str(), &end);
    else x = static_cast<T>(std::strtod(s.c_str(), &end));
    if (end != s.c_str() + s.size()) return std::errc::invalid_argument;
    if (errno == ERANGE && std::isinf(x)) return std::errc::result_out_of_range;
    v = x;
    return std::errc();
}

// Parses all of s into v (an integer or floating-point type): std::errc() on success,
// result_out_of_range for a number beyond T, invalid_argument for anything else.
template <class T>
std::errc parseWhole(const std::string& s, T& v) {
#if !defined(__cpp_lib_to_chars)
    if constexpr (std::is_floating_point_v<T>) {
        return parseFloatWithStrtod(s, v);
    } else
#endif
    {
        T x{};
        auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), x);
        if (ec != std::errc()) return ec;
        if (end != s.data() + s.size()) return std::errc::invalid_argument;
        v = x;
        return std::errc();
    }
}

}  // namespace ps
