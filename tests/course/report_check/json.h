// A strict JSON reader (RFC 8259) for report_check: the whole text must be one value, with
// nothing a lenient reader would forgive (trailing commas, comments, NaN, leading zeros, raw
// control characters in strings, bad escapes, invalid UTF-8, a key twice in one object).
// A mistake throws ParseError naming the line and column.
#pragma once
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "utf8.h"

namespace reportcheck {

struct ParseError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct Json {
    enum Kind { Null, Bool, Number, String, Array, Object } kind = Null;
    bool boolean = false;
    double number = 0;
    std::string text;                                   // String
    std::vector<Json> items;                            // Array
    std::vector<std::pair<std::string, Json>> members;  // Object, in order
    const Json* find(const std::string& key) const {
        for (const auto& [k, v] : members)
            if (k == key) return &v;
        return nullptr;
    }
};

inline const char* kindName(Json::Kind k) {
    const char* names[] = {"null", "a boolean", "a number", "a string", "an array", "an object"};
    return names[k];
}

class JsonReader {
public:
    explicit JsonReader(const std::string& s) : s_(s) {}

    Json document() {
        if (!validUtf8(s_)) fail("the text is not valid UTF-8");
        Json v = value();
        space();
        if (p_ != s_.size()) fail("text after the end of the document");
        return v;
    }

private:
    const std::string& s_;
    size_t p_ = 0;

    [[noreturn]] void fail(const std::string& what) const {
        size_t line = 1, col = 1;
        for (size_t i = 0; i < p_ && i < s_.size(); ++i) s_[i] == '\n' ? (++line, col = 1) : ++col;
        throw ParseError("line " + std::to_string(line) + ", column " + std::to_string(col) + ": " + what);
    }
    void space() {
        while (p_ < s_.size() && (s_[p_] == ' ' || s_[p_] == '\t' || s_[p_] == '\n' || s_[p_] == '\r')) ++p_;
    }
    bool eat(char c) {
        space();
        if (p_ < s_.size() && s_[p_] == c) return ++p_, true;
        return false;
    }
    void expect(char c) {
        if (!eat(c)) fail(std::string("expected '") + c + "'");
    }
    bool word(const char* w) {
        const std::string t(w);
        if (s_.compare(p_, t.size(), t) != 0) return false;
        p_ += t.size();
        return true;
    }

    Json value() {
        space();
        if (p_ >= s_.size()) fail("unexpected end of the document");
        Json v;
        const char c = s_[p_];
        if (c == '{') return object();
        if (c == '[') return array();
        if (c == '"') return v.kind = Json::String, v.text = string(), v;
        if (word("true")) return v.kind = Json::Bool, v.boolean = true, v;
        if (word("false")) return v.kind = Json::Bool, v;
        if (word("null")) return v;
        if (c == '-' || (c >= '0' && c <= '9')) return number();
        fail(std::string("unexpected character '") + c + "'");
    }

    Json object() {
        Json v;
        v.kind = Json::Object;
        expect('{');
        if (eat('}')) return v;
        do {
            space();
            if (p_ >= s_.size() || s_[p_] != '"') fail("expected a key in quotes");
            std::string key = string();
            if (v.find(key)) fail("the key \"" + key + "\" twice in one object");
            expect(':');
            v.members.emplace_back(key, value());
        } while (eat(','));
        expect('}');
        return v;
    }

    Json array() {
        Json v;
        v.kind = Json::Array;
        expect('[');
        if (eat(']')) return v;
        do v.items.push_back(value());
        while (eat(','));
        expect(']');
        return v;
    }

    // RFC 8259, section 6: -? (0 | [1-9][0-9]*) (.[0-9]+)? ([eE][+-]?[0-9]+)?
    Json number() {
        const size_t start = p_;
        auto digits = [&] {
            const size_t d = p_;
            while (p_ < s_.size() && s_[p_] >= '0' && s_[p_] <= '9') ++p_;
            if (p_ == d) fail("a number needs digits here");
        };
        if (s_[p_] == '-') ++p_;
        if (p_ < s_.size() && s_[p_] == '0') ++p_;
        else digits();
        if (p_ < s_.size() && s_[p_] == '.') ++p_, digits();
        if (p_ < s_.size() && (s_[p_] == 'e' || s_[p_] == 'E')) {
            ++p_;
            if (p_ < s_.size() && (s_[p_] == '+' || s_[p_] == '-')) ++p_;
            digits();
        }
        if (p_ < s_.size() && s_[p_] >= '0' && s_[p_] <= '9') fail("a number with a leading zero");
        Json v;
        v.kind = Json::Number;
        v.number = std::stod(s_.substr(start, p_ - start));
        return v;
    }

    unsigned hex4() {
        if (p_ + 4 > s_.size()) fail("a \\u escape needs four hex digits");
        unsigned u = 0;
        for (int i = 0; i < 4; ++i, ++p_) {
            const char c = s_[p_];
            const int d = c >= '0' && c <= '9'   ? c - '0'
                          : c >= 'a' && c <= 'f' ? c - 'a' + 10
                          : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                                 : -1;
            if (d < 0) fail("a \\u escape needs four hex digits");
            u = u * 16 + d;
        }
        return u;
    }

    std::string string() {
        ++p_;  // the opening quote
        std::string out;
        for (;;) {
            if (p_ >= s_.size()) fail("a string without its closing quote");
            const unsigned char c = s_[p_++];
            if (c == '"') return out;
            if (c < 0x20) fail("a control character in a string (it must be escaped)");
            if (c != '\\') {
                out += static_cast<char>(c);
                continue;
            }
            if (p_ >= s_.size()) fail("a string without its closing quote");
            const char e = s_[p_++];
            switch (e) {
            case '"': out += '"'; break;
            case '\\': out += '\\'; break;
            case '/': out += '/'; break;
            case 'b': out += '\b'; break;
            case 'f': out += '\f'; break;
            case 'n': out += '\n'; break;
            case 'r': out += '\r'; break;
            case 't': out += '\t'; break;
            case 'u': {
                unsigned u = hex4();
                if (u >= 0xd800 && u <= 0xdbff) {  // a surrogate pair
                    if (!word("\\u")) fail("a high surrogate without its low surrogate");
                    const unsigned low = hex4();
                    if (low < 0xdc00 || low > 0xdfff) fail("a high surrogate without its low surrogate");
                    u = 0x10000 + ((u - 0xd800) << 10) + (low - 0xdc00);
                } else if (u >= 0xdc00 && u <= 0xdfff) fail("a low surrogate alone");
                appendUtf8(out, u);
                break;
            }
            default: fail(std::string("an unknown escape \\") + e);
            }
        }
    }
};

}  // namespace reportcheck
