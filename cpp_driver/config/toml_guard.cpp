// toml++ 3.3's defects kept away from it: the text it is given is checked, and cleaned,
// before it parses it (config/case_toml.hpp).
#include <algorithm>
#include <cctype>

#include "config/case_toml.hpp"

namespace sphjet::casefile {

namespace {

// ---------------------------------------------------------------------------------------
// Three toml++ 3.3 defects, kept away from it.
// ---------------------------------------------------------------------------------------

// toml++ 3.3 (the Debian 12 package) has defects that malformed text reaches, all found
// by tests/fuzz (-fsanitize=undefined on toml++ compiled header-only):
//  - a table header whose key starts with a character that cannot start a key ("[^x]",
//    "[[[1]]]", "[" at the end of a line) fails an assertion in parse_key() (abort without
//    NDEBUG, an assumption that does not hold with it); fixed upstream in
//    marzer/tomlplusplus pull 301;
//  - a non-ASCII character where toml++ tests for whitespace (after a key, in the text it
//    scans ahead of a bare value, after a backslash in a multi-line string) reaches
//    TOML_UNREACHABLE in its Unicode tables: undefined behaviour in every build;
//    marzer/tomlplusplus reports 190 and 295, fixed by pull 305.

// The first line that starts (after blanks) with '[' or '[[' not followed by a key, ']' or
// another '[' toml++ reports itself: its byte offset. Line by line, without regard to
// strings, so a multi-line string or array holding such a line is reported too (the format
// has neither).
std::optional<std::size_t> bad_table_header(std::string_view text) {
    const auto blank = [](char c) { return c == ' ' || c == '\t'; };
    const auto key_start = [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '"' || c == '\'';
    };
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text = text.substr(3);  // UTF-8 byte-order mark
    for (std::size_t b = 0; b < text.size();) {
        std::size_t e = text.find('\n', b);
        if (e == std::string_view::npos) e = text.size();
        std::size_t i = b;
        while (i < e && blank(text[i])) ++i;
        if (i < e && text[i] == '[') {
            ++i;
            bool had_blank = false;
            while (i < e && blank(text[i])) ++i, had_blank = true;
            if (i < e && text[i] == '[' && !had_blank) {  // "[ [" is an error toml++ reports
                ++i;
                while (i < e && blank(text[i])) ++i;
            }
            if (i < text.size() && text[i] != ']' && !(had_blank && text[i] == '[') && !key_start(text[i]))
                return i;
        }
        b = e + 1;
    }
    return std::nullopt;
}

// Length of the well-formed UTF-8 sequence of a non-ASCII character at s[i] (0: none).
std::size_t utf8_length(std::string_view s, std::size_t i) {
    const auto u = [&](std::size_t k) { return k < s.size() ? static_cast<unsigned char>(s[k]) : 0u; };
    const auto cont = [&](std::size_t k, unsigned lo = 0x80, unsigned hi = 0xBF) { return u(k) >= lo && u(k) <= hi; };
    const unsigned c = u(i);
    if (c >= 0xC2 && c <= 0xDF) return cont(i + 1) ? 2 : 0;
    if (c == 0xE0) return cont(i + 1, 0xA0) && cont(i + 2) ? 3 : 0;
    if ((c >= 0xE1 && c <= 0xEC) || c == 0xEE || c == 0xEF) return cont(i + 1) && cont(i + 2) ? 3 : 0;
    if (c == 0xED) return cont(i + 1, 0x80, 0x9F) && cont(i + 2) ? 3 : 0;
    if (c == 0xF0) return cont(i + 1, 0x90) && cont(i + 2) && cont(i + 3) ? 4 : 0;
    if (c >= 0xF1 && c <= 0xF3) return cont(i + 1) && cont(i + 2) && cont(i + 3) ? 4 : 0;
    if (c == 0xF4) return cont(i + 1, 0x80, 0x8F) && cont(i + 2) && cont(i + 3) ? 4 : 0;
    return 0;
}

// The text toml++ is given: every non-ASCII character replaced by '?'. TOML allows those
// characters only in comments and strings; every key and string value of this format is
// ASCII, so a case file means the same after the replacement (a wrong value or key is
// quoted with '?' in its message) and columns, counted in characters, stay the same.
// Malformed UTF-8 is left for toml++ to report.
std::string ascii_for_toml(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const std::size_t n = utf8_length(text, i);
        if (n == 0) {
            out += text[i++];
        } else {
            out += '?';
            i += n;
        }
    }
    return out;
}

// Two more defects fail the assertion !is_value_terminator in parse_value() (abort without
// NDEBUG, an unmet assumption with it):
//  - in an array, a '}' where a value is expected ("a = [}", "[1, }", also after blank lines
//    and comments);
//  - a bare value of ten characters with '-' at the 5th and 8th (a date's shape), then a
//    space, one digit and a value terminator ("a = 1979-05-27 7 "): toml++ takes the space
//    for the date-time separator and scans on past the digit. Never valid TOML (a time after
//    the space needs hh:mm:ss). toml++ counts the ten characters without the underscores
//    ("a = 1_979-05-27 7 " has the shape too) and ends a value also at '\v' and '\f'.
// The offset of the first, from a small lexer (comments and the four kinds of string): toml++
// reaches either only through text that parses, which the lexer follows exactly.
// toml++'s value terminators in ASCII: whitespace ('\v' and '\f' among it), ',', ']', '}', '#'.
bool toml_terminator(char c) {
    return c == ' ' || c == '\t' || (c >= '\n' && c <= '\r') || c == ',' || c == ']' || c == '}' || c == '#';
}

// Whether the bare value at text[i] is what toml++ takes for a date with a space before the
// time, followed by one digit and a terminator. Its ten characters are counted as toml++
// counts them, without '_'; a value with '_' in them is refused whatever follows the digit
// (never a date, and toml++ steps back over the underscores too).
bool date_space_digit(std::string_view text, std::size_t i) {
    const auto digit = [](char c) { return c >= '0' && c <= '9'; };
    std::string shape;
    std::size_t j = i;
    for (; j < text.size() && !toml_terminator(text[j]) && shape.size() <= 10; ++j)
        if (text[j] != '_') shape += text[j];
    if (shape.size() != 10 || !digit(shape[0]) || shape[4] != '-' || shape[7] != '-') return false;
    if (j + 1 >= text.size() || text[j] != ' ' || !digit(text[j + 1])) return false;
    if (j - i != 10) return true;
    return j + 2 < text.size() && toml_terminator(text[j + 2]);
}

std::optional<std::size_t> toml_assertion_hazard(std::string_view text) {
    enum class S { Normal, Comment, Basic, Literal, MlBasic, MlLiteral } s = S::Normal;
    std::vector<char> open;     // '[' (array) or '{' (inline table), innermost last
    bool expect_value = false;  // just after '[' or ',' of an array
    bool line_begin = true;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\n') {
            if (s == S::Comment || s == S::Basic || s == S::Literal) s = S::Normal;
            line_begin = true;
            continue;
        }
        switch (s) {
            case S::Normal: {
                const bool header = line_begin && open.empty();
                if (c == ' ' || c == '\t' || c == '\r') break;
                line_begin = false;
                if (c == '#') {
                    s = S::Comment;
                    break;
                }
                if (expect_value && c == '}') return i;
                if ((i == 0 || toml_terminator(text[i - 1]) || std::string_view("=[{").find(text[i - 1]) != std::string_view::npos) &&
                    date_space_digit(text, i))
                    return i;
                expect_value = false;
                if (c == '"' || c == '\'') {
                    const bool multi = text.substr(i, 3) == std::string(3, c);
                    s = c == '"' ? (multi ? S::MlBasic : S::Basic) : (multi ? S::MlLiteral : S::Literal);
                    if (multi) i += 2;
                } else if (c == '[' && !header) {
                    open.push_back('['), expect_value = true;
                } else if (c == '[' && header) {  // a table header: to the end of its line
                    while (i + 1 < text.size() && text[i + 1] != '\n') ++i;
                } else if (c == '{') {
                    open.push_back('{');
                } else if ((c == ']' || c == '}') && !open.empty()) {
                    open.pop_back();
                } else if (c == ',' && !open.empty() && open.back() == '[') {
                    expect_value = true;
                }
                break;
            }
            case S::Comment:
                break;
            case S::Basic:
                if (c == '\\' && i + 1 < text.size() && text[i + 1] != '\n') ++i;
                else if (c == '"') s = S::Normal;
                break;
            case S::Literal:
                if (c == '\'') s = S::Normal;
                break;
            case S::MlBasic:
            case S::MlLiteral: {
                const char q = s == S::MlBasic ? '"' : '\'';
                if (s == S::MlBasic && c == '\\' && i + 1 < text.size() && text[i + 1] != '\n') {
                    ++i;
                } else if (c == q && text.substr(i, 3) == std::string(3, q)) {
                    std::size_t j = i;
                    while (j < text.size() && text[j] == q && j - i < 5) ++j;
                    i = j - 1;
                    s = S::Normal;
                }
                break;
            }
        }
    }
    return std::nullopt;
}

bool has_non_ascii(std::string_view s) {
    return std::any_of(s.begin(), s.end(), [](char c) { return static_cast<unsigned char>(c) >= 0x80; });
}


}  // namespace

bool safe_for_toml(std::string_view line) {
    return !has_non_ascii(line) && !bad_table_header(line) && !toml_assertion_hazard(line);
}

toml::table parse_toml(std::string_view text, const std::string& source_name) {
    if (const auto bad = bad_table_header(text)) {
        const std::size_t pos = *bad + (text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0);
        std::size_t line = 1, start = 0;
        for (std::size_t k = 0; k < pos; ++k)
            if (text[k] == '\n') ++line, start = k + 1;
        const unsigned char c = static_cast<unsigned char>(text[pos]);
        std::string found = "'" + std::string(1, static_cast<char>(c)) + "'";
        if (c == '\n' || c == '\r') found = "the end of the line";
        else if (c < 0x20 || c >= 0x7f) found = "byte " + std::to_string(c);
        throw InputError(source_name + ":" + std::to_string(line) + ":" + std::to_string(pos - start + 1),
                         "TOML syntax error: a table header without a key",
                         "a bare key (letters, digits, _ or -) or a quoted key after '[' or '[['", found);
    }
    const std::string toml_text = ascii_for_toml(text);
    if (const auto bad = toml_assertion_hazard(toml_text)) {
        std::size_t line = 1, start = 0;
        for (std::size_t k = 0; k < *bad; ++k)
            if (toml_text[k] == '\n') ++line, start = k + 1;
        throw InputError(source_name + ":" + std::to_string(line) + ":" + std::to_string(*bad - start + 1),
                         "TOML syntax error", toml_text[*bad] == '}' ? "a value or ']'" : "a valid value",
                         toml_text[*bad] == '}' ? "'}' in an array" : "a date followed by a space and one digit (toml++ counts the date's characters without '_')");
    }
    try {
        return toml::parse(toml_text, source_name);
    } catch (const toml::parse_error& e) {
        const auto& b = e.source().begin;
        throw InputError(source_name + ":" + std::to_string(b.line) + ":" + std::to_string(b.column),
                         "TOML syntax error: " + std::string(e.description()));
    }
}

}  // namespace sphjet::casefile
