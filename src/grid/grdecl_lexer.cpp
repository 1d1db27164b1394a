#include "grid/grdecl_lexer.h"

#include <charconv>

namespace cutaway::grid {

static bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }

void GrdeclLexer::skip_blanks_and_comments() {
    while (pos_ < text_.size()) {
        const char c = text_[pos_];
        if (c == '\n') {
            ++line_;
            ++pos_;
        } else if (is_blank(c)) {
            ++pos_;
        } else if (c == '-' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '-') {
            while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
        } else {
            return;
        }
    }
}

Token GrdeclLexer::peek() {
    GrdeclLexer copy = *this;
    return copy.next();
}

Token GrdeclLexer::next() {
    skip_blanks_and_comments();
    Token token;
    token.line = line_;
    token.first_on_line = line_ != last_token_line_;
    if (pos_ >= text_.size()) return token;
    last_token_line_ = line_;

    const char c = text_[pos_];
    if (c == '/') {
        ++pos_;
        token.kind = TokenKind::slash;
        token.text = text_.substr(pos_ - 1, 1);
        return token;
    }
    if (c == '\'' || c == '"') {
        const std::size_t start = ++pos_;
        while (pos_ < text_.size() && text_[pos_] != c && text_[pos_] != '\n') ++pos_;
        token.kind = TokenKind::quoted;
        token.text = text_.substr(start, pos_ - start);
        if (pos_ < text_.size() && text_[pos_] == c)
            ++pos_;
        else
            unterminated_quote_ = true;
        return token;
    }
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !is_blank(text_[pos_]) && text_[pos_] != '/' && text_[pos_] != '\'' &&
           text_[pos_] != '"')
        ++pos_;
    token.kind = TokenKind::word;
    token.text = text_.substr(start, pos_ - start);
    return token;
}

RepeatItem split_repeat(std::string_view word) {
    const std::size_t star = word.find('*');
    if (star == std::string_view::npos) return {1, word, true};
    RepeatItem item;
    item.value = word.substr(star + 1);
    const std::string_view count = word.substr(0, star);
    const auto [end, error] = std::from_chars(count.data(), count.data() + count.size(), item.count);
    item.valid = error == std::errc() && end == count.data() + count.size() && item.count > 0;
    return item;
}

}  // namespace cutaway::grid
