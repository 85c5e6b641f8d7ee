// Recursive-descent reader for the module-call structure of scene files and
// for the expressions of their arguments, evaluated as they are read.

#include "scene/reading/scene_syntax.h"

#include "scene/reading/scene_args.h"
#include "scene/reading/scene_expression.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string_view>
#include <vector>

namespace capsim::scene_file {
namespace {

constexpr double kPi = 3.14159265358979323846;  // OpenSCAD's PI (M_PI)

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

class Reader {
 public:
  Reader(const Tokens& tokens, std::pmr::memory_resource* memory, double t)
      : tokens_(tokens), memory_(memory), t_(t), statements_in_(count_statements(tokens)) {}

  std::pmr::vector<Call> file(Loc* end) {
    std::pmr::vector<Call> calls(memory_);
    calls.reserve(statements_in_[0]);
    while (peek().kind != TokenKind::End) statement(calls);
    if (end) *end = peek().loc;
    return calls;
  }

 private:
  static bool is_symbol(const Token& t, std::string_view s) {
    return t.kind == TokenKind::Symbol && t.text == s;
  }

  // The calls each list of calls will hold, read ahead from the tokens, so
  // that each list is made once at its size: a monotonic resource never reuses
  // what a growing list leaves behind, and a file's one union of thousands of
  // objects would leave twice its size. Entry 0 is the file's own list, entry
  // k the list of the call body opened by the file's k-th '{'. A call ends
  // with ';' after its ')' or with the '}' of a body opened after its ')';
  // it is counted in the list of the innermost body around it (or the file),
  // a bare block's calls going to the list the block is in. A count is only
  // an allocation's size: whatever the tokens, the lists hold what is read.
  static std::vector<std::uint32_t> count_statements(const Tokens& tokens) {
    std::vector<std::uint32_t> counts(1, 0);
    std::vector<std::size_t> owners(1, 0);  // per '{' open, the list its calls go to
    std::vector<bool> body_ends;            // per '{' open: its '}' ends a call
    for (std::size_t i = 0; i < tokens.size(); ++i) {
      const Token& t = tokens[i];
      if (t.kind != TokenKind::Symbol) continue;
      const bool after_call = i > 0 && is_symbol(tokens[i - 1], ")");
      if (t.text == "{") {
        counts.push_back(0);
        owners.push_back(after_call ? counts.size() - 1 : owners.back());
        body_ends.push_back(after_call);
      } else if (t.text == "}" && !body_ends.empty()) {
        const bool ends_call = body_ends.back();
        owners.pop_back();
        body_ends.pop_back();
        if (ends_call) ++counts[owners.back()];
      } else if (t.text == ";" && after_call) {
        ++counts[owners.back()];
      }
    }
    return counts;
  }

  const Token& peek(size_t ahead = 0) const {
    size_t i = pos_ + ahead;
    return i < tokens_.size() ? tokens_[i] : tokens_.back();
  }
  const Token& take() {
    const Token& t = tokens_[pos_];
    if (pos_ + 1 < tokens_.size()) ++pos_;
    return t;
  }
  bool at_symbol(std::string_view s, size_t ahead = 0) const { return is_symbol(peek(ahead), s); }
  // Every syntax error comes here. One at the end of the file, or at a name
  // that is the file's last token (a complete file ends with ';' or '}'),
  // means the file ends inside a statement: a truncated file, reported as
  // such rather than as, say, an unknown variable cut short.
  [[noreturn]] void fail(const Token& t, const std::string& message) const {
    const Token& end = tokens_.back();
    if (t.kind == TokenKind::End) {
      constexpr std::string_view kGotEnd = ", got end of file";
      std::string_view expected = message;
      if (expected.ends_with(kGotEnd)) expected.remove_suffix(kGotEnd.size());
      throw SceneError(t.loc, fmt::format("unexpected end of file: {}", expected));
    }
    if (t.kind == TokenKind::Identifier && &t == &end - 1) {
      throw SceneError(end.loc, fmt::format("unexpected end of file after '{}'", t.text));
    }
    throw SceneError(t.loc, message);
  }

  // One level of nesting, entered at `opener` (the first token of a call's
  // children, '{' or '[') for as long as it lives.
  class Nesting {
   public:
    Nesting(Reader& reader, const Token& opener) : reader_(reader) {
      if (++reader_.depth_ > kMaxNestingDepth) {
        reader_.fail(opener, fmt::format("nesting deeper than {} levels is not supported (calls' "
                                         "children, {{ }} blocks, [ ] vectors and the ( ), ? "
                                         "and ^ of expressions inside one another)",
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
      ++braces_taken_;
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
      call.children.reserve(statements_in_[++braces_taken_]);
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
      call.args.push_back(Argument{name, name_loc, argument_value()});
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
    if (closer == "]" && at_symbol(":")) {
      fail(t, "ranges [start:step:end] are not supported; write the vector out");
    }
    if (t.kind == TokenKind::End) {
      fail(t, fmt::format("missing '{}': expected ',' or '{}'", closer, closer));
    }
    fail(t, fmt::format("expected ',' or '{}', got {}", closer, describe(t)));
  }

  // An argument: an expression whose value, and every number in it, is finite.
  Value argument_value() {
    Value v = expression();
    check_finite(v);
    return v;
  }

  void check_finite(const Value& v) const {
    if (v.kind == Value::Kind::Number && !std::isfinite(v.number)) refuse_not_finite(v);
    for (const Value& e : v.items) check_finite(e);
  }

  [[noreturn, gnu::noinline]] static void refuse_not_finite(const Value& v) {
    throw SceneError(v.loc, fmt::format("the expression gives {}, not a finite number; every number "
                                        "must be finite",
                                        std::isnan(v.number) ? "nan" : v.number > 0 ? "inf" : "-inf"));
  }

  // Expressions are evaluated as they are read, with $t given. The parts
  // OpenSCAD would not evaluate (the branch of `? :` not taken, the right
  // side of `&&` or `||` that does not decide) are read in a dead stretch:
  // checked for syntax, names and argument counts, not evaluated, so that
  // `$t > 0 ? 1 / $t : 0` works as it does in OpenSCAD.
  bool live() const { return dead_ == 0; }
  class DeadIf {
   public:
    DeadIf(Reader& reader, bool dead) : reader_(reader), dead_(dead) { reader_.dead_ += dead_; }
    ~DeadIf() { reader_.dead_ -= dead_; }
    DeadIf(const DeadIf&) = delete;
    DeadIf& operator=(const DeadIf&) = delete;

   private:
    Reader& reader_;
    int dead_;
  };

  // The expression reader recurses a few frames per level of nesting (a
  // '(' or '[' or a function's arguments, a '?' or a '^'), so, as for calls,
  // its recursive functions keep their frames small: each builds its result
  // in place (the value it returns), and the work with more locals (a right
  // operand, the branches of '? :', a message) is done in helpers kept out of
  // line.

  // expression := binary(1) ['?' expression ':' expression]
  Value expression() {
    Value v = binary(1);
    if (at_symbol("?")) choose(v);
    return v;
  }

  // After the condition `v` of '? :': replaces it with the branch taken.
  [[gnu::noinline]] void choose(Value& v) {
    const Token& question = peek();
    Nesting level(*this, question);
    take();
    const bool taken = live() && truthy(v);
    const Loc loc = v.loc;
    {
      DeadIf dead(*this, !taken);
      Value yes = expression();
      if (taken) v = std::move(yes);
    }
    if (!at_symbol(":")) refuse_missing_colon(question);
    take();
    {
      DeadIf dead(*this, taken);
      Value no = expression();
      if (!taken) v = std::move(no);
    }
    v.loc = loc;
  }

  [[noreturn, gnu::noinline]] void refuse_missing_colon(const Token& question) const {
    fail(peek(), fmt::format("expected ':' of the '?' at {}:{}, got {}", question.loc.line,
                             question.loc.col, describe(peek())));
  }

  // The binary operator at pos_ and its precedence (OpenSCAD's parser.y:
  // || < && < == != < comparisons < + - < * / %), or level 0 if none.
  struct BinaryAt {
    int level = 0;
    BinaryOp op = BinaryOp::Plus;
  };
  BinaryAt binary_at() const {
    const Token& t = peek();
    if (t.kind != TokenKind::Symbol) return {};
    // Most values of a scene are followed by ',', ')' or ']': one switch
    // on the first character settles those.
    const bool two = t.text.size() == 2;
    switch (t.text[0]) {
      case '|': return two ? BinaryAt{1, BinaryOp::Or} : BinaryAt{};
      case '&': return two ? BinaryAt{2, BinaryOp::And} : BinaryAt{};
      case '=': return two ? BinaryAt{3, BinaryOp::Equal} : BinaryAt{};
      case '!': return two ? BinaryAt{3, BinaryOp::NotEqual} : BinaryAt{};
      case '<': return {4, two ? BinaryOp::LessEqual : BinaryOp::Less};
      case '>': return {4, two ? BinaryOp::GreaterEqual : BinaryOp::Greater};
      case '+': return {5, BinaryOp::Plus};
      case '-': return {5, BinaryOp::Minus};
      case '*': return {6, BinaryOp::Times};
      case '/': return {6, BinaryOp::Divide};
      case '%': return {6, BinaryOp::Modulo};
      default: return {};
    }
  }

  // Operators of `min_level` and tighter, left-associative. The recursion for
  // a right operand goes at most one frame per level, however long the chain.
  Value binary(int min_level) {
    Value lhs = unary();
    for (BinaryAt at = binary_at(); at.level >= min_level && at.level > 0; at = binary_at()) {
      apply_operator(lhs, at);
    }
    return lhs;
  }

  // Reads the operator `at` at pos_ and its right operand, and applies it to lhs.
  [[gnu::noinline]] void apply_operator(Value& lhs, BinaryAt at) {
    const Token& op = take();
    // || and && skip their right side when the left decides.
    const bool decided = live() && ((at.op == BinaryOp::Or && truthy(lhs)) ||
                                    (at.op == BinaryOp::And && !truthy(lhs)));
    DeadIf dead(*this, decided);
    Value rhs = binary(at.level + 1);
    if (decided) {
      set_bool(lhs, at.op == BinaryOp::Or);
    } else if (!live()) {
      return;
    } else if (at.op == BinaryOp::Or || at.op == BinaryOp::And) {
      set_bool(lhs, truthy(rhs));  // the left did not decide: the right does
    } else {
      lhs = apply_binary(at.op, lhs, rhs, op, memory_);
    }
  }

  static void set_bool(Value& v, bool b) {
    v.kind = Value::Kind::Bool;
    v.boolean = b;
    v.items.clear();
  }

  // unary := {'+' | '-' | '!'} exponent, the operators applied right to left
  // (a loop: a long run of signs costs no stack).
  Value unary() {
    const size_t first = pos_;
    while (at_symbol("-") || at_symbol("+") || at_symbol("!")) {
      if (at_symbol("-") && peek(1).kind == TokenKind::Identifier &&
          (peek(1).text == "inf" || peek(1).text == "nan")) {
        refuse_negative_infinity();
      }
      take();
    }
    const size_t last = pos_;
    Value v = exponent();
    if (last != first && live()) apply_signs(v, first, last);
    return v;
  }

  [[noreturn, gnu::noinline]] void refuse_negative_infinity() const {
    fail(peek(), fmt::format("'-{}' is not a finite number; every number must be finite",
                             peek(1).text));
  }

  // Applies the signs tokens_[first, last) to v, the last one first.
  [[gnu::noinline]] void apply_signs(Value& v, size_t first, size_t last) {
    for (size_t i = last; i-- > first;) {
      const Token& op = tokens_[i];
      if (op.text == "-") {
        v = negate(v, op, memory_);
      } else if (op.text == "!") {
        set_bool(v, !truthy(v));
      }
      v.loc = op.loc;
    }
  }

  // exponent := primary ['^' unary]: right-associative, and tighter than a
  // sign on its left (-2^2 is -4), as in OpenSCAD. What OpenSCAD allows after
  // a primary but scene files do not is refused here.
  Value exponent() {
    Value base = primary();
    if (at_symbol("^")) {
      raise(base);
    } else if (at_symbol("[") || at_symbol(".") || at_symbol("(")) {
      refuse_postfix();
    }
    return base;
  }

  [[gnu::noinline]] void raise(Value& base) {
    Nesting level(*this, peek());
    const Token& op = take();
    Value power = unary();
    if (live()) base = apply_binary(BinaryOp::Power, base, power, op, memory_);
  }

  [[noreturn, gnu::noinline]] void refuse_postfix() const {
    if (at_symbol("[")) {
      fail(peek(), "indexing a value ('[...]' after it) is not supported in scene files");
    }
    if (at_symbol(".")) {
      fail(peek(), "member access ('.x', '.y', '.z') is not supported in scene files");
    }
    fail(peek(), "only the built-in functions can be called, by name");
  }

  // primary := number | string | name | name '(' args ')' | '(' expression ')'
  //          | '[' [expression {',' expression} [',']] ']'
  Value primary() {
    const Token& t = peek();
    switch (t.kind) {
      case TokenKind::Number: {
        take();
        Value v(memory_, t.loc);
        v.kind = Value::Kind::Number;
        v.number = t.number;
        return v;
      }
      case TokenKind::String: return string_literal();
      case TokenKind::Identifier: return identifier_value();
      case TokenKind::End: refuse_value();
      case TokenKind::Symbol: break;
    }
    if (t.text == "(") return group();
    if (t.text != "[") refuse_value();
    return vector_value();
  }

  [[gnu::noinline]] Value string_literal() {
    const Token& t = take();
    Value v(memory_, t.loc);
    v.kind = Value::Kind::String;
    v.string = string_value(t.text);
    return v;
  }

  // '(' expression ')'
  [[gnu::noinline]] Value group() {
    const Token& open = peek();
    Nesting level(*this, open);
    take();
    Value inner = expression();
    if (!at_symbol(")")) refuse_unclosed_group(open);
    take();
    inner.loc = open.loc;
    return inner;
  }

  [[noreturn, gnu::noinline]] void refuse_unclosed_group(const Token& open) const {
    if (peek().kind == TokenKind::End) refuse_unclosed(open, '(', ')');
    fail(peek(), fmt::format("expected ')' closing the '(' at {}:{}, got {}", open.loc.line,
                             open.loc.col, describe(peek())));
  }

  // '[' [expression {',' expression} [',']] ']'
  [[gnu::noinline]] Value vector_value() {
    const Token& t = peek();
    Nesting level(*this, t);
    take();
    Value v(memory_, t.loc);
    v.kind = Value::Kind::Vector;
    size_t first = pending_items_.size();
    while (!at_symbol("]")) {
      if (peek().kind == TokenKind::End) refuse_unclosed(t, '[', ']');
      pending_items_.push_back(expression());
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

  // Why the token at pos_ does not start a value.
  [[noreturn, gnu::noinline]] void refuse_value() const {
    if (peek().kind == TokenKind::End) fail(peek(), "expected a value");
    fail(peek(), fmt::format("expected a value, got {}", describe(peek())));
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

  // true, false, undef, $t, PI or a call of a built-in function.
  [[gnu::noinline]] Value identifier_value() {
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
    if (is_language_keyword(t.text)) refuse_name(t);
    if (at_symbol("(")) return function_call(t);
    if (t.text == "$t" || t.text == "PI") {
      v.kind = Value::Kind::Number;
      v.number = t.text == "$t" ? t_ : kPi;
      return v;
    }
    refuse_name(t);
  }

  [[noreturn, gnu::noinline]] void refuse_name(const Token& t) const {
    if (t.text == "inf" || t.text == "nan") {
      fail(t, fmt::format("'{}' is not a finite number; every number must be finite", t.text));
    }
    if (is_language_keyword(t.text)) {
      fail(t, fmt::format("'{}' is not supported in scene-file expressions", t.text));
    }
    fail(t, fmt::format("unknown variable '{}': expressions may use only $t (the animation time) "
                        "and PI",
                        t.text));
  }

  // name '(' [expression {',' expression}] ')', after the name.
  [[gnu::noinline]] Value function_call(const Token& name) {
    const Arity arity = function_arity(name.text);
    if (!arity.known()) refuse_function(name);
    Nesting level(*this, peek());
    const Token& open = take();  // '('
    const size_t first = pending_items_.size();
    while (!at_symbol(")")) {
      if (peek().kind == TokenKind::End) refuse_unclosed(open, '(', ')');
      if (peek().kind == TokenKind::Identifier && at_symbol("=", 1)) refuse_named_argument(name);
      pending_items_.push_back(expression());
      if (at_symbol(",")) {
        take();
      } else if (!at_symbol(")")) {
        after_value(")");
      }
    }
    take();
    const size_t count = pending_items_.size() - first;
    if (static_cast<int>(count) < arity.min || (arity.max >= 0 && static_cast<int>(count) > arity.max)) {
      refuse_argument_count(name, arity, count);
    }
    Value result(memory_, name.loc);
    if (live()) {
      result = call_function(name, std::span<const Value>(pending_items_).subspan(first), memory_);
    }
    pending_items_.erase(pending_items_.begin() + static_cast<std::ptrdiff_t>(first),
                         pending_items_.end());
    return result;
  }

  [[noreturn, gnu::noinline]] void refuse_named_argument(const Token& name) const {
    fail(peek(), fmt::format("named arguments are not supported in function calls ('{} = ...' in "
                             "{}())",
                             peek().text, name.text));
  }

  [[noreturn, gnu::noinline]] void refuse_function(const Token& name) const {
    std::vector<std::string> known;
    for (std::string_view n : {"sin", "cos", "tan", "asin", "acos", "atan", "atan2", "abs", "sign",
                               "sqrt", "pow", "exp", "ln", "log", "min", "max", "floor", "ceil",
                               "round", "lookup"}) {
      known.emplace_back(n);
    }
    const std::string guess = closest_name(name.text, known);
    fail(name, fmt::format("unknown function '{}'{}; supported: {}", name.text,
                           guess.empty() ? "" : fmt::format(" (did you mean '{}'?)", guess),
                           function_names()));
  }

  [[noreturn, gnu::noinline]] void refuse_argument_count(const Token& name, Arity arity,
                                                         size_t count) const {
    const std::string takes =
        arity.max < 0         ? fmt::format("at least {}", arity.min)
        : arity.min == arity.max ? fmt::format("{}", arity.min)
                                 : fmt::format("{} or {}", arity.min, arity.max);
    fail(name, fmt::format("{}() takes {} argument{}, got {}", name.text, takes,
                           takes == "1" ? "" : "s", count));
  }

  const Tokens& tokens_;
  std::pmr::memory_resource* memory_;
  double t_;  // the value of $t
  size_t pos_ = 0;
  int depth_ = 0;  // levels of nesting open at pos_
  int dead_ = 0;   // dead stretches open at pos_ (see live())
  // The items of the vectors being read, innermost last. Collecting them here
  // rather than growing each vector's own list gives every vector a single
  // allocation of its final size (a monotonic resource never reuses what a
  // growing list leaves behind).
  std::vector<Value> pending_items_;
  // count_statements' counts, and the '{' tokens taken so far: every '{' the
  // reader meets is taken by statement() or body(), in the file's order.
  std::vector<std::uint32_t> statements_in_;
  std::size_t braces_taken_ = 0;
};

}  // namespace

std::pmr::vector<Call> read_calls(const Tokens& tokens,
                                  std::pmr::memory_resource* memory, Loc* end, double t) {
  return Reader(tokens, memory, t).file(end);
}

}  // namespace capsim::scene_file
