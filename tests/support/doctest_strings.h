// Included before every test source (tests/support/CMakeLists.txt, -include): failure messages
// print C strings as text. Without this, doctest prints a `const char*` that is not a string
// literal, e.g. the result of `cond ? "hit" : "missed"`, as a pointer address. (Its own switch
// DOCTEST_CONFIG_TREAT_CHAR_STAR_AS_STRING does not compile in Debian's doctest 2.4.9.)
#pragma once
#include <doctest/doctest.h>

namespace doctest {
template <>
struct StringMaker<const char*> {
    static String convert(const char* s) { return s ? String(s) : String("(null)"); }
};
template <>
struct StringMaker<char*> {
    static String convert(const char* s) { return s ? String(s) : String("(null)"); }
};
}  // namespace doctest
