#pragma once
// Splits GRDECL text into tokens: words (keywords, numbers, `N*value` items), quoted strings and
// `/` terminators, skipping white space and `--` comments, counting lines.
#include <cstddef>
#include <string_view>

namespace cutaway::grid {

enum class TokenKind { word, quoted, slash, end };

struct Token {
    TokenKind kind = TokenKind::end;
    std::string_view text;  // without quotes for TokenKind::quoted
    int line = 0;           // 1-based
    bool first_on_line = false;
};

class GrdeclLexer {
public:
    explicit GrdeclLexer(std::string_view text) : text_(text) {}

    /// The next token; TokenKind::end at the end of the text. An unterminated quote yields a
    /// quoted token running to the end of its line, with `unterminated_quote()` set.
    Token next();
    Token peek();
    int line() const { return line_; }
    bool unterminated_quote() const { return unterminated_quote_; }

private:
    void skip_blanks_and_comments();

    std::string_view text_;
    std::size_t pos_ = 0;
    int line_ = 1;
    std::size_t line_start_pos_ = 0;
    int last_token_line_ = 0;
    bool unterminated_quote_ = false;
};

/// An item of a value list: `value`, `N*value` or `N*` (a default).
struct RepeatItem {
    std::size_t count = 1;
    std::string_view value;  // empty for a default (`N*`)
    bool valid = true;       // false when the repeat count is not a positive integer
};

RepeatItem split_repeat(std::string_view word);

}  // namespace cutaway::grid
