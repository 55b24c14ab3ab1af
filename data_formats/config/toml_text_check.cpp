// A small TOML lexer that tracks only whether each character is outside any
// string or comment, in a string (and which kind), or in a comment, and for
// text outside, whether a key or a value is being read. The parser reads a
// bare value to its end before judging it ("5.'x'" and "1x.{" are single
// tokens), so quotes and brackets only open strings, arrays and tables where
// a key or value can start; the rest stays "outside", where non-ASCII
// characters are refused.
#include "data_formats/config/toml_text_check.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include <fmt/format.h>

#include "data_formats/error.h"

namespace skybake {
namespace {

// toml++ skips a UTF-8 byte order mark at the start of a document.
constexpr std::string_view kUtf8ByteOrderMark = "\xEF\xBB\xBF";
constexpr std::string_view kMultiLineBasic = "\"\"\"";
constexpr std::string_view kMultiLineLiteral = "'''";

// The code points toml++ 3.3's is_non_ascii_horizontal_whitespace() does not
// handle (its generated lookup table misses them), found by evaluating that
// function over the whole range it tests, U+00A0 to U+FEFF.
struct CodePointRange {
  char32_t first;
  char32_t last;
};
constexpr CodePointRange kMisreadCodePoints[] = {
    {0x00A1, 0x0499}, {0x2C5E, 0x2FFF}, {0x3001, 0x3057}, {0xFB26, 0xFEFE}};

// The non-ASCII code points toml++ 3.3 takes for horizontal whitespace: it
// skips them after a line-ending backslash as it skips spaces.
constexpr CodePointRange kNonAsciiHorizontalWhitespace[] = {{0x00A0, 0x00A0}, {0x1680, 0x1680}, {0x180E, 0x180E},
                                                            {0x2000, 0x200B}, {0x202F, 0x202F}, {0x205F, 0x2060},
                                                            {0x3000, 0x3000}, {0xFEFF, 0xFEFF}};

bool isAscii(char c) { return static_cast<unsigned char>(c) < 0x80; }
bool isTomlWhitespaceOrNewline(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

template <size_t N>
bool inRanges(char32_t c, const CodePointRange (&ranges)[N]) {
  for (const CodePointRange& range : ranges) {
    if (c >= range.first && c <= range.last) return true;
  }
  return false;
}

struct DecodedCodePoint {
  char32_t code = 0;  // 0 when not well formed (the parser refuses those itself)
  size_t length = 1;  // bytes
};

// The UTF-8 sequence at the start of `text` (not empty).
DecodedCodePoint decodeUtf8(std::string_view text) {
  const auto lead = static_cast<unsigned char>(text[0]);
  const size_t length = lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC0 ? 2 : 1;
  if (length == 1 || text.size() < length) return {};
  char32_t code = lead & (0x7F >> length);
  for (size_t i = 1; i < length; ++i) {
    const auto next = static_cast<unsigned char>(text[i]);
    if ((next & 0xC0) != 0x80) return {};
    code = (code << 6) | (next & 0x3F);
  }
  return {code, length};
}

enum class Context { Outside, Comment, BasicString, LiteralString, MultiLineBasic, MultiLineLiteral };

// What encloses the text outside strings: arrays and inline tables nest;
// a table header holds keys up to its ']'.
enum class Bracket { Array, InlineTable, TableHeader };

class Scanner {
 public:
  Scanner(std::string_view text, const std::string& source) : text_(text), source_(source) {}

  void scan() {
    if (startsWith(kUtf8ByteOrderMark)) position_ = kUtf8ByteOrderMark.size();
    while (position_ < text_.size()) step();
  }

 private:
  bool startsWith(std::string_view s) const { return text_.substr(position_, s.size()) == s; }
  char current() const { return text_[position_]; }
  bool atEnd() const { return position_ >= text_.size(); }
  char previous() const { return position_ > 0 ? text_[position_ - 1] : '\n'; }

  void advance() {
    if (current() == '\n') {
      ++line_;
      line_start_ = position_ + 1;
    }
    ++position_;
  }

  void advance(size_t n) {
    for (size_t i = 0; i < n; ++i) advance();
  }

  [[noreturn]] void fail(const std::string& reason) const {
    int column = 1;  // in code points, as the parser counts
    for (size_t i = line_start_; i < position_; ++i) column += (text_[i] & 0xC0) != 0x80;
    throwBadInput(fmt::format("{}:{}:{}: TOML syntax error: {}", source_, line_, column, reason));
  }

  // Where the parser stops reading a bare value ("5", "true", a date).
  static bool endsValueToken(char c) {
    return isTomlWhitespaceOrNewline(c) || c == ']' || c == '}' || c == ',' || c == '#';
  }

  // Whether a quote in a key starts a string: at the start of the key or a
  // dotted part of it. After a bare key character the parser stops at the
  // quote itself.
  bool quoteStartsKeyString() const {
    const char p = previous();
    return isTomlWhitespaceOrNewline(p) || p == '.' || p == '[' || p == '{' || p == ',';
  }

  void openString(char quote) {
    const bool multi_line = startsWith(quote == '"' ? kMultiLineBasic : kMultiLineLiteral);
    if (quote == '"') context_ = multi_line ? Context::MultiLineBasic : Context::BasicString;
    if (quote == '\'') context_ = multi_line ? Context::MultiLineLiteral : Context::LiteralString;
    advance(multi_line ? kMultiLineBasic.size() : 1);
  }

  // A string just ended: in a value, whatever follows it up to a token's end
  // is one malformed token.
  void closeString() {
    context_ = Context::Outside;
    if (!reading_key_) in_value_token_ = true;
  }

  void stepOutside(char c) {
    if (!isAscii(c)) fail("non-ASCII character outside a string or comment");
    if (endsValueToken(c)) {
      in_value_token_ = false;
    } else if (in_value_token_) {
      // Inside a bare value the parser reads quotes and brackets as part of
      // the token ("1x.{" is one malformed value), so they open nothing.
      return advance();
    } else if (c == '"' || c == '\'') {
      if (!reading_key_ || quoteStartsKeyString()) return openString(c);
    } else if (!reading_key_ && c != '[' && c != '{') {
      in_value_token_ = true;
    }
    const bool in_array = !brackets_.empty() && brackets_.back() == Bracket::Array;
    switch (c) {
      case '#':
        context_ = Context::Comment;
        break;
      case '\n':
        if (brackets_.empty()) reading_key_ = true;
        if (brackets_.empty()) key_levels_ = 0;
        break;
      case '.':
        if (reading_key_) {
          ++key_levels_;
          checkNesting(value_depth_ + key_levels_ + 1);
        }
        break;
      case '=':
        reading_key_ = false;
        value_key_levels_ = key_levels_ + 1;  // a key of n dots nests n + 1 tables
        key_levels_ = 0;
        break;
      case ',':
        reading_key_ = !in_array;
        key_levels_ = 0;
        value_key_levels_ = 0;
        break;
      case '{':
        openValueBracket(Bracket::InlineTable);
        reading_key_ = true;
        break;
      case '[':
        if (reading_key_ && (brackets_.empty() || brackets_.back() == Bracket::TableHeader)) {
          // A table header: its keys nest from the document's root.
          brackets_.push_back(Bracket::TableHeader);
          value_depth_ = 0;
          key_levels_ = 0;
        } else {
          openValueBracket(Bracket::Array);
        }
        break;
      case ']':
      case '}': {
        const bool closes_header = !brackets_.empty() && brackets_.back() == Bracket::TableHeader;
        if (!brackets_.empty()) brackets_.pop_back();
        if (closes_header) {
          // The keys of the table below the header nest under it.
          if (brackets_.empty()) value_depth_ = key_levels_ + 1;
          key_levels_ = 0;
        } else {
          reading_key_ = false;  // the array or inline table was a value
          if (!depth_at_open_.empty()) {
            value_depth_ = depth_at_open_.back();
            depth_at_open_.pop_back();
          }
          value_key_levels_ = 0;
        }
        break;
      }
      default:
        break;
    }
    advance();
  }

  // An array or inline table opens as the value of the key just read, the
  // key's last level, or as an element of an enclosing array, one level
  // below it.
  void openValueBracket(Bracket bracket) {
    brackets_.push_back(bracket);
    depth_at_open_.push_back(value_depth_);
    value_depth_ += std::max(value_key_levels_, 1);  // the key's last table is this bracket (an element: one level)
    value_key_levels_ = 0;
    key_levels_ = 0;
    checkNesting(value_depth_);
  }

  void checkNesting(int depth) const {
    if (depth > kMaxTomlNesting) {
      fail(
          fmt::format("nested more than {} levels deep (tables, dotted keys, arrays and inline tables "
                      "counted together; a skybake config needs at most 4)",
                      kMaxTomlNesting));
    }
  }

  // Skips a multi-line string's closing delimiter with the up to two quotes
  // TOML lets stand before it (""""" is two quotes and the end).
  void closeMultiLine(char quote) {
    while (!atEnd() && current() == quote) advance();
    closeString();
  }

  // After a backslash in a multi-line basic string (the backslash consumed):
  // the parser tests the next character, and after a line-ending backslash
  // the first one that is not whitespace, for whitespace.
  void escapeInMultiLineBasic() {
    if (atEnd()) return;
    if (!isAscii(current())) fail("a backslash must be followed by an escape code, not a non-ASCII character");
    if (!isTomlWhitespaceOrNewline(current())) {
      advance();  // the escape code
      return;
    }
    for (;;) {
      if (atEnd()) return;
      if (isTomlWhitespaceOrNewline(current())) {
        advance();
        continue;
      }
      if (isAscii(current())) return;
      const DecodedCodePoint next = decodeUtf8(text_.substr(position_));
      if (inRanges(next.code, kNonAsciiHorizontalWhitespace)) {
        advance(next.length);
        continue;
      }
      if (!inRanges(next.code, kMisreadCodePoints)) return;
      const auto code = static_cast<uint32_t>(next.code);
      fail(
          fmt::format("in a multi-line string, the text after a line-ending backslash cannot start "
                      "with U+{:04X}, which the TOML parser misreads there; write it as \\u{:04X}",
                      code, code));
    }
  }

  void step() {
    const char c = current();
    switch (context_) {
      case Context::Outside:
        return stepOutside(c);
      case Context::Comment:
        if (c != '\n') return advance();
        context_ = Context::Outside;  // the newline ending a comment is one outside it
        return stepOutside(c);
      case Context::BasicString:
        advance();
        if (c == '\\' && !atEnd()) advance();      // an escaped quote does not end the string
        if (c == '"' || c == '\n') closeString();  // a newline is the parser's error
        return;
      case Context::LiteralString:
        advance();
        if (c == '\'' || c == '\n') closeString();
        return;
      case Context::MultiLineBasic:
        if (startsWith(kMultiLineBasic)) return closeMultiLine('"');
        advance();
        if (c == '\\') escapeInMultiLineBasic();
        return;
      case Context::MultiLineLiteral:
        if (startsWith(kMultiLineLiteral)) return closeMultiLine('\'');
        advance();
        return;
    }
  }

  std::string_view text_;
  const std::string& source_;
  Context context_ = Context::Outside;
  bool reading_key_ = true;      // a document starts with keys
  bool in_value_token_ = false;  // inside a bare value, or after a string in one
  std::vector<Bracket> brackets_;
  // Nesting, for kMaxTomlNesting: the tables enclosing the current value
  // (from the table header and the open arrays and inline tables), the dots
  // of the key being read, and the levels the key before '=' adds to its value.
  int value_depth_ = 0;
  int key_levels_ = 0;
  int value_key_levels_ = 0;
  std::vector<int> depth_at_open_;  // value_depth_ where each open array or inline table began
  size_t position_ = 0;
  int line_ = 1;
  size_t line_start_ = 0;
};

}  // namespace

void checkTomlCharacters(std::string_view text, const std::string& source) { Scanner(text, source).scan(); }

}  // namespace skybake
