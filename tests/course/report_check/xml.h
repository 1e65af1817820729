// A strict reader for the XML that JUnit reports are made of (XML 1.0: an optional declaration,
// comments, one root element; elements with attributes, text, CDATA and character references).
// Not accepted, as any XML reader would not: tags that do not match, an attribute twice, '<' or
// a bare '&' in an attribute or text, an unknown entity, a character XML 1.0 forbids (control
// characters other than tab, newline and carriage return, also as &#N;), invalid UTF-8. No DTD.
// A mistake throws ParseError (json.h) naming the line and column.
#pragma once
#include <cctype>
#include <string>
#include <vector>

#include "json.h"
#include "utf8.h"

namespace reportcheck {

struct Element {
    std::string name;
    std::vector<std::pair<std::string, std::string>> attributes;  // in order
    std::vector<Element> children;
    std::string text;  // the character data directly inside, concatenated
    int line = 0;
    const std::string* attribute(const std::string& key) const {
        for (const auto& [k, v] : attributes)
            if (k == key) return &v;
        return nullptr;
    }
};

class XmlReader {
public:
    explicit XmlReader(const std::string& s) : s_(s) {}

    Element document() {
        if (!validUtf8(s_)) fail("the text is not valid UTF-8");
        if (word("<?xml")) skipPast("?>");
        misc();
        if (!word("<")) fail("expected the root element");
        Element root = element();
        misc();
        if (p_ != s_.size()) fail("text after the root element");
        return root;
    }

private:
    const std::string& s_;
    size_t p_ = 0;

    int line() const {
        int n = 1;
        for (size_t i = 0; i < p_ && i < s_.size(); ++i) n += s_[i] == '\n';
        return n;
    }
    [[noreturn]] void fail(const std::string& what) const {
        size_t col = 1;
        for (size_t i = 0; i < p_ && i < s_.size(); ++i) col = s_[i] == '\n' ? 1 : col + 1;
        throw ParseError("line " + std::to_string(line()) + ", column " + std::to_string(col) + ": " + what);
    }
    bool word(const std::string& w) {
        if (s_.compare(p_, w.size(), w) != 0) return false;
        p_ += w.size();
        return true;
    }
    void skipPast(const std::string& end) {
        const size_t e = s_.find(end, p_);
        if (e == std::string::npos) fail("no closing " + end);
        p_ = e + end.size();
    }
    void space() {
        while (p_ < s_.size() && (s_[p_] == ' ' || s_[p_] == '\t' || s_[p_] == '\n' || s_[p_] == '\r')) ++p_;
    }
    // Whitespace, comments and processing instructions outside the root element.
    void misc() {
        for (;;) {
            space();
            if (word("<!--")) skipPast("-->");
            else if (s_.compare(p_, 9, "<!DOCTYPE") == 0) fail("a DTD (not in a JUnit report)");
            else if (s_.compare(p_, 2, "<?") == 0) p_ += 2, skipPast("?>");
            else return;
        }
    }
    std::string name() {
        const size_t start = p_;
        auto first = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_' || c == ':'; };
        auto rest = [&](char c) {
            return first(c) || std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '.';
        };
        if (p_ >= s_.size() || !first(s_[p_])) fail("expected a name");
        while (p_ < s_.size() && rest(s_[p_])) ++p_;
        return s_.substr(start, p_ - start);
    }
    // XML 1.0's Char production, for the characters below U+0080 and for references.
    void allowed(unsigned cp) const {
        if ((cp < 0x20 && cp != 0x9 && cp != 0xa && cp != 0xd) || (cp >= 0xd800 && cp <= 0xdfff) || cp == 0xfffe ||
            cp == 0xffff || cp > 0x10ffff)
            fail("a character XML 1.0 does not allow (code " + std::to_string(cp) + ")");
    }
    // Character data up to `stop` ('<' for text, the quote for an attribute), references resolved.
    std::string chars(char stop) {
        std::string out;
        while (p_ < s_.size() && s_[p_] != stop) {
            const char c = s_[p_];
            if (c == '<') fail("'<' inside an attribute value");
            if (c != '&') {
                allowed(static_cast<unsigned char>(c) < 0x80 ? static_cast<unsigned char>(c) : 0x80);
                out += c, ++p_;
                continue;
            }
            const size_t semi = s_.find(';', p_);
            if (semi == std::string::npos || semi - p_ > 12) fail("a bare '&' (write &amp;)");
            const std::string ref = s_.substr(p_ + 1, semi - p_ - 1);
            if (ref.empty() || ref.find_first_of(" \t\n\r&<\"'") != std::string::npos) fail("a bare '&' (write &amp;)");
            if (ref == "amp") out += '&';
            else if (ref == "lt") out += '<';
            else if (ref == "gt") out += '>';
            else if (ref == "quot") out += '"';
            else if (ref == "apos") out += '\'';
            else if (ref.size() > 1 && ref[0] == '#') {
                const bool hex = ref[1] == 'x';
                const std::string digits = ref.substr(hex ? 2 : 1);
                if (digits.empty() ||
                    digits.find_first_not_of(hex ? "0123456789abcdefABCDEF" : "0123456789") != std::string::npos)
                    fail("a bad character reference &" + ref + ";");
                const unsigned long cp = std::stoul(digits, nullptr, hex ? 16 : 10);
                allowed(static_cast<unsigned>(cp > 0x110000 ? 0x110000 : cp));
                appendUtf8(out, static_cast<unsigned>(cp));
            } else fail("an unknown entity &" + ref + ";");
            p_ = semi + 1;
        }
        return out;
    }
    // After '<': the element, its content and its end tag.
    Element element() {
        Element e;
        e.line = line();
        e.name = name();
        for (;;) {
            const size_t before = p_;
            space();
            if (word("/>")) return e;
            if (word(">")) break;
            if (p_ == before) fail("expected a space, '>' or '/>' in the tag of <" + e.name + ">");
            std::string key = name();
            if (e.attribute(key)) fail("the attribute " + key + " twice in <" + e.name + ">");
            space();
            if (!word("=")) fail("expected '=' after the attribute " + key);
            space();
            if (p_ >= s_.size() || (s_[p_] != '"' && s_[p_] != '\'')) fail("an attribute value needs quotes");
            const char quote = s_[p_++];
            std::string value = chars(quote);
            if (!word(std::string(1, quote))) fail("an attribute value without its closing quote");
            e.attributes.emplace_back(key, value);
        }
        for (;;) {  // content
            if (p_ >= s_.size()) fail("<" + e.name + "> is never closed");
            if (word("</")) {
                const std::string end = name();
                if (end != e.name) fail("</" + end + "> closes <" + e.name + ">");
                space();
                if (!word(">")) fail("expected '>' after </" + end);
                return e;
            }
            if (word("<!--")) skipPast("-->");
            else if (word("<![CDATA[")) {
                const size_t end = s_.find("]]>", p_);
                if (end == std::string::npos) fail("a CDATA section without its end");
                for (; p_ < end; ++p_) {
                    allowed(static_cast<unsigned char>(s_[p_]) < 0x80 ? static_cast<unsigned char>(s_[p_]) : 0x80);
                    e.text += s_[p_];
                }
                p_ = end + 3;
            } else if (word("<?")) skipPast("?>");
            else if (word("<")) e.children.push_back(element());
            else e.text += chars('<');
        }
    }
};

}  // namespace reportcheck
