// Recursive-descent reader for the module-call structure of scene files.

#include "scene_syntax.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <iterator>
#include <string_view>

namespace capsim::scene_file {
namespace {

constexpr std::string_view kPlainTree =
    "scene files hold a plain CSG tree as 'openscad -o model.csg model.scad' writes it; "
    "export the model with OpenSCAD first";

// OpenSCAD language keywords that are statements of their own in a .scad file.
constexpr std::array<std::string_view, 12> kLanguageKeywords = {
    "module", "function", "if",     "else", "for",     "intersection_for",
    "let",    "each",     "assert", "echo", "include", "use"};

bool is_language_keyword(std::string_view name) {
  for (std::string_view k : kLanguageKeywords) {
    if (k == name) return true;
  }
  return false;
}

// Symbols that, right after a value, can only continue an expression.
bool is_operator(const Token& t) {
  static constexpr std::array<std::string_view, 19> kOps = {"+",  "-", "*",  "/",  "%",  "^",  "?",
                                                            "<",  ">", "==", "!=", "<=", ">=", "&&",
                                                            "||", ".", "[",  "(",  "!"};
  if (t.kind != TokenKind::Symbol) return false;
  for (std::string_view op : kOps) {
    if (op == t.text) return true;
  }
  return false;
}

class Reader {
 public:
  Reader(const std::vector<Token>& tokens, std::pmr::memory_resource* memory)
      : tokens_(tokens), memory_(memory) {}

  std::pmr::vector<Call> file(Loc* end) {
    std::pmr::vector<Call> calls(memory_);
    while (peek().kind != TokenKind::End) statement(calls);
    if (end) *end = peek().loc;
    return calls;
  }

 private:
  const Token& peek(size_t ahead = 0) const {
    size_t i = pos_ + ahead;
    return i < tokens_.size() ? tokens_[i] : tokens_.back();
  }
  const Token& take() {
    const Token& t = tokens_[pos_];
    if (pos_ + 1 < tokens_.size()) ++pos_;
    return t;
  }
  bool at_symbol(std::string_view s, size_t ahead = 0) const {
    const Token& t = peek(ahead);
    return t.kind == TokenKind::Symbol && t.text == s;
  }
  [[noreturn]] void fail(const Token& t, const std::string& message) const {
    throw SceneError(t.loc, message);
  }

  // One level of nesting, entered at `opener` (the first token of a call's
  // children, '{' or '[') for as long as it lives.
  class Nesting {
   public:
    Nesting(Reader& reader, const Token& opener) : reader_(reader) {
      if (++reader_.depth_ > kMaxNestingDepth) {
        reader_.fail(opener, fmt::format("nesting deeper than {} levels is not supported (calls' "
                                         "children, {{ }} blocks and [ ] vectors inside one "
                                         "another)",
                                         kMaxNestingDepth));
      }
    }
    ~Nesting() { --reader_.depth_; }
    Nesting(const Nesting&) = delete;
    Nesting& operator=(const Nesting&) = delete;

   private:
    Reader& reader_;
  };

  static bool is_modifier(const Token& t) {
    return t.kind == TokenKind::Symbol &&
           (t.text == "%" || t.text == "#" || t.text == "!" || t.text == "*");
  }

  // The reader recurses a few frames per level of nesting, up to
  // kMaxNestingDepth levels, so the recursive functions keep their frames
  // small: a call is built in place in its list, and messages are composed in
  // helpers kept out of line.

  // statement := ';' | '{' statement* '}' | modifier* call
  // Appends what it reads to `out` (a bare block's statements go straight in).
  void statement(std::pmr::vector<Call>& out) {
    if (at_symbol(";")) {
      take();
      return;
    }
    if (at_symbol("{")) {
      Nesting level(*this, peek());
      const Token& open = take();
      block_rest(open, out);
      return;
    }
    // Built where it stays: while it is read, only its own lists grow, never
    // `out`.
    Call& call = out.emplace_back(memory_);
    while (is_modifier(peek())) {
      const Token& m = take();
      call.modifiers.push_back(Modifier{m.text[0], m.loc});
    }
    const Token& head = peek();
    if (head.kind != TokenKind::Identifier || is_language_keyword(head.text) ||
        !at_symbol("(", 1)) {
      refuse_call_head(call);
    }
    call.name = head.text;
    call.loc = head.loc;
    take();
    arguments(call);
    body(call);
  }

  // Why the tokens after `call`'s modifiers do not start a call.
  [[noreturn, gnu::noinline]] void refuse_call_head(const Call& call) const {
    const Token& head = peek();
    if (head.kind != TokenKind::Identifier) {
      if (!call.modifiers.empty()) {
        fail(head, fmt::format("expected an object after modifier '{}', got {}",
                               call.modifiers.back().symbol, describe(head)));
      }
      fail(head, fmt::format("expected an object such as sphere(), cube() or cylinder(), got {}",
                             describe(head)));
    }
    if (is_language_keyword(head.text)) {
      fail(head, fmt::format("'{}' is not supported: {}", head.text, kPlainTree));
    }
    if (at_symbol("=", 1)) {
      fail(head, fmt::format("variable assignment '{} = ...' is not supported: {}", head.text,
                             kPlainTree));
    }
    fail(peek(1), fmt::format("expected '(' after '{}', got {}", head.text, describe(peek(1))));
  }

  // After an opening '{': statements up to the matching '}'.
  void block_rest(const Token& open, std::pmr::vector<Call>& out) {
    while (!at_symbol("}")) {
      if (peek().kind == TokenKind::End) refuse_unclosed(open, '{', '}');
      statement(out);
    }
    take();
  }

  // The end of the file where `open`'s closing `close` should be.
  [[noreturn, gnu::noinline]] void refuse_unclosed(const Token& open, char opening,
                                                   char close) const {
    fail(peek(), fmt::format("missing '{}': the '{}' at {}:{} is not closed", close, opening,
                             open.loc.line, open.loc.col));
  }

  // body := ';' | '{' statement* '}' | statement (a single child)
  void body(Call& call) {
    if (at_symbol(";")) {
      take();
      return;
    }
    call.has_body = true;
    call.body_loc = peek().loc;
    Nesting level(*this, peek());
    if (at_symbol("{")) {
      const Token& open = take();
      block_rest(open, call.children);
      return;
    }
    const Token& next = peek();
    if (next.kind != TokenKind::Identifier && !is_modifier(next)) refuse_body(call);
    statement(call.children);
  }

  [[noreturn, gnu::noinline]] void refuse_body(const Call& call) const {
    fail(peek(), fmt::format("expected ';', '{{' or a child object after {}(...), got {}",
                             call.name, describe(peek())));
  }

  // arguments := '(' [argument {',' argument} [',']] ')'
  void arguments(Call& call) {
    const Token& open = take();  // '('
    Loc open_loc = open.loc;
    while (!at_symbol(")")) {
      if (peek().kind == TokenKind::End) {
        fail(peek(), fmt::format("missing ')': the '(' of {} at {}:{} is not closed", call.name,
                                 open_loc.line, open_loc.col));
      }
      std::string_view name;
      Loc name_loc;
      if (peek().kind == TokenKind::Identifier && at_symbol("=", 1)) {
        const Token& name_token = take();
        name = name_token.text;
        name_loc = name_token.loc;
        take();  // '='
      }
      call.args.push_back(Argument{name, name_loc, value()});
      if (at_symbol(",")) {
        take();
      } else if (!at_symbol(")")) {
        after_value(")");
      }
    }
    take();  // ')'
  }

  // Something other than the expected separator follows a complete value.
  [[noreturn, gnu::noinline]] void after_value(std::string_view closer) {
    const Token& t = peek();
    if (is_operator(t)) {
      fail(t, fmt::format("expressions are not supported (found operator '{}' after a value); "
                          "write every argument as a literal number, string, vector, true, "
                          "false or undef",
                          t.text));
    }
    if (closer == "]" && at_symbol(":")) {
      fail(t, "ranges [start:step:end] are not supported; write the vector out");
    }
    if (t.kind == TokenKind::End) {
      fail(t, fmt::format("missing '{}': expected ',' or '{}', got end of file", closer, closer));
    }
    fail(t, fmt::format("expected ',' or '{}', got {}", closer, describe(t)));
  }

  // value := number | '-' number | string | true | false | undef | '[' values ']'
  Value value() {
    const Token& t = peek();
    Value v(memory_, t.loc);
    switch (t.kind) {
      case TokenKind::Number:
        take();
        v.kind = Value::Kind::Number;
        v.number = t.number;
        return v;
      case TokenKind::String:
        take();
        v.kind = Value::Kind::String;
        v.string = string_value(t.text);
        return v;
      case TokenKind::Identifier: return identifier_value();
      case TokenKind::End: fail(t, "expected a value, got end of file");
      case TokenKind::Symbol: break;
    }
    if (t.text == "-" && peek(1).kind == TokenKind::Number) {
      take();
      const Token& n = take();
      v.kind = Value::Kind::Number;
      v.number = -n.number;
      return v;
    }
    if (t.text != "[") refuse_value();
    Nesting level(*this, t);
    take();
    v.kind = Value::Kind::Vector;
    size_t first = pending_items_.size();
    while (!at_symbol("]")) {
      if (peek().kind == TokenKind::End) refuse_unclosed(t, '[', ']');
      pending_items_.push_back(value());
      if (at_symbol(",")) {
        take();
      } else if (!at_symbol("]")) {
        after_value("]");
      }
    }
    take();
    take_pending_items(first, v.items);
    return v;
  }

  // Why the symbol at pos_ does not start a value.
  [[noreturn, gnu::noinline]] void refuse_value() const {
    const Token& t = peek();
    if (t.text == "-" && peek(1).kind == TokenKind::Identifier &&
        (peek(1).text == "inf" || peek(1).text == "nan")) {
      fail(t,
           fmt::format("'-{}' is not a finite number; every number must be finite", peek(1).text));
    }
    if (t.text == "-" || t.text == "+" || t.text == "!" || t.text == "(") {
      fail(t, fmt::format("expressions are not supported (found '{}'); write every argument as "
                          "a literal number, string, vector, true, false or undef",
                          t.text));
    }
    fail(t, fmt::format("expected a value, got {}", describe(t)));
  }

  // The value of a string written as `raw`: a view of the scene text itself
  // unless escapes must be decoded, then of a decoded copy in the parse's memory.
  std::string_view string_value(std::string_view raw) const {
    if (raw.find('\\') == std::string_view::npos) return raw;
    std::string decoded = decode_string(raw);
    char* kept = static_cast<char*>(memory_->allocate(decoded.size(), 1));
    std::copy(decoded.begin(), decoded.end(), kept);
    return std::string_view(kept, decoded.size());
  }

  // Moves the pending items from index `first` on into `items`, sized exactly.
  void take_pending_items(size_t first, std::pmr::vector<Value>& items) {
    auto begin = pending_items_.begin() + static_cast<std::ptrdiff_t>(first);
    items.assign(std::make_move_iterator(begin), std::make_move_iterator(pending_items_.end()));
    pending_items_.erase(begin, pending_items_.end());
  }

  Value identifier_value() {
    const Token& t = take();
    Value v(memory_, t.loc);
    if (t.text == "true" || t.text == "false") {
      v.kind = Value::Kind::Bool;
      v.boolean = t.text == "true";
      return v;
    }
    if (t.text == "undef") {
      v.kind = Value::Kind::Undef;
      return v;
    }
    if (t.text == "inf" || t.text == "nan") {
      fail(t, fmt::format("'{}' is not a finite number; every number must be finite", t.text));
    }
    if (at_symbol("(")) {
      fail(t, fmt::format("function calls are not supported ('{}(...)'); write the value as a "
                          "literal number, string, vector, true, false or undef",
                          t.text));
    }
    fail(t, fmt::format("variables are not supported ('{}'); write the value as a literal "
                        "number, string, vector, true, false or undef",
                        t.text));
  }

  const std::vector<Token>& tokens_;
  std::pmr::memory_resource* memory_;
  size_t pos_ = 0;
  int depth_ = 0;  // levels of nesting open at pos_
  // The items of the vectors being read, innermost last. Collecting them here
  // rather than growing each vector's own list gives every vector a single
  // allocation of its final size (a monotonic resource never reuses what a
  // growing list leaves behind).
  std::vector<Value> pending_items_;
};

}  // namespace

std::pmr::vector<Call> read_calls(const std::vector<Token>& tokens,
                                  std::pmr::memory_resource* memory, Loc* end) {
  return Reader(tokens, memory).file(end);
}

}  // namespace capsim::scene_file
