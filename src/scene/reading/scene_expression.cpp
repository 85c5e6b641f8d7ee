// OpenSCAD 2021.01's value semantics for scene-file expressions: operators as
// its value.cc defines them, built-in functions as its func.cc does, and its
// degree trigonometry (degree_trig.cc).

#include "scene/reading/scene_expression.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "scene/reading/scene_args.h"

namespace capsim::scene_file {
namespace {

constexpr double kSqrt1_2 = 0.70710678118654752440;
constexpr double kSqrt3 = 1.73205080756887719318;
constexpr double kSqrt3_4 = 0.86602540378443859659;  // sqrt(3) / 2
constexpr double kSqrt1_3 = 0.57735026918962573106;  // sqrt(3) / 3
// Past this, an angle in degrees has no fractional bits left to reduce
// (26 + 26 bits of mantissa): the result would mean nothing.
constexpr double kTrigHuge = double(1L << 26) * 360.0 * double(1L << 26);

constexpr double kRad2Deg = 57.2957795130823208767;   // 180 / pi
constexpr double kDeg2Rad = 0.017453292519943295769;  // pi / 180

double rad2deg(double x) { return x * kRad2Deg; }
double deg2rad(double x) { return x * kDeg2Rad; }

std::string_view op_symbol(BinaryOp op) {
  switch (op) {
    case BinaryOp::Or: return "||";
    case BinaryOp::And: return "&&";
    case BinaryOp::Equal: return "==";
    case BinaryOp::NotEqual: return "!=";
    case BinaryOp::Less: return "<";
    case BinaryOp::LessEqual: return "<=";
    case BinaryOp::Greater: return ">";
    case BinaryOp::GreaterEqual: return ">=";
    case BinaryOp::Plus: return "+";
    case BinaryOp::Minus: return "-";
    case BinaryOp::Times: return "*";
    case BinaryOp::Divide: return "/";
    case BinaryOp::Modulo: return "%";
    case BinaryOp::Power: return "^";
  }
  return "?";
}

Value number(double x, Loc loc, std::pmr::memory_resource* memory) {
  Value v(memory, loc);
  v.kind = Value::Kind::Number;
  v.number = x;
  return v;
}

Value boolean(bool b, Loc loc, std::pmr::memory_resource* memory) {
  Value v(memory, loc);
  v.kind = Value::Kind::Bool;
  v.boolean = b;
  return v;
}

Value vector(Loc loc, std::pmr::memory_resource* memory) {
  Value v(memory, loc);
  v.kind = Value::Kind::Vector;
  return v;
}

[[noreturn, gnu::noinline]] void refuse_operands(BinaryOp op, const Value& a, const Value& b,
                                                 const Token& at, std::string_view accepted) {
  throw SceneError(at.loc, fmt::format("operator '{}' takes {}, got {} and {}", op_symbol(op),
                                       accepted, describe(a), describe(b)));
}

bool is_number(const Value& v) { return v.kind == Value::Kind::Number; }
bool is_vector(const Value& v) { return v.kind == Value::Kind::Vector; }

bool equal(const Value& a, const Value& b) {
  if (a.kind != b.kind) return false;
  switch (a.kind) {
    case Value::Kind::Undef: return true;
    case Value::Kind::Bool: return a.boolean == b.boolean;
    case Value::Kind::Number: return a.number == b.number;
    case Value::Kind::String: return a.string == b.string;
    case Value::Kind::Vector:
      if (a.items.size() != b.items.size()) return false;
      for (size_t i = 0; i < a.items.size(); ++i) {
        if (!equal(a.items[i], b.items[i])) return false;
      }
      return true;
  }
  return false;
}

// a < b, a <= b, ... for two numbers, two booleans or two strings.
bool compare(BinaryOp op, const Value& a, const Value& b, const Token& at) {
  const auto decide = [op](const auto& x, const auto& y) {
    switch (op) {
      case BinaryOp::Less: return x < y;
      case BinaryOp::LessEqual: return x <= y;
      case BinaryOp::Greater: return x > y;
      default: return x >= y;
    }
  };
  if (a.kind == b.kind) {
    if (a.kind == Value::Kind::Number) return decide(a.number, b.number);
    if (a.kind == Value::Kind::Bool) return decide(a.boolean, b.boolean);
    if (a.kind == Value::Kind::String) return decide(a.string, b.string);
  }
  refuse_operands(op, a, b, at, "two numbers, two booleans or two strings");
}

// a + b or a - b: numbers, or vectors element by element (truncated to the
// shorter, as OpenSCAD does).
Value add(BinaryOp op, const Value& a, const Value& b, const Token& at,
          std::pmr::memory_resource* memory) {
  if (is_number(a) && is_number(b)) {
    return number(op == BinaryOp::Plus ? a.number + b.number : a.number - b.number, a.loc, memory);
  }
  if (!is_vector(a) || !is_vector(b)) refuse_operands(op, a, b, at, "two numbers or two vectors");
  Value sum = vector(a.loc, memory);
  const size_t n = std::min(a.items.size(), b.items.size());
  sum.items.reserve(n);
  for (size_t i = 0; i < n; ++i) sum.items.push_back(add(op, a.items[i], b.items[i], at, memory));
  return sum;
}

// Every number of a (nested) vector combined with a number.
template <typename Combine>
Value each_number(const Value& v, const Combine& combine, std::pmr::memory_resource* memory) {
  if (is_number(v)) return number(combine(v.number), v.loc, memory);
  Value out = vector(v.loc, memory);
  out.items.reserve(v.items.size());
  for (const Value& e : v.items) {
    if (!is_number(e) && !is_vector(e)) return Value(memory, e.loc);  // undef marks a refusal
    Value r = each_number(e, combine, memory);
    if (r.kind == Value::Kind::Undef) return r;
    out.items.push_back(std::move(r));
  }
  return out;
}

Value multiply(const Value& a, const Value& b, const Token& at, std::pmr::memory_resource* memory) {
  constexpr std::string_view kAccepted = "two numbers, a number and a vector, or two vectors of numbers of the same length";
  if (is_number(a) && is_number(b)) return number(a.number * b.number, a.loc, memory);
  if (is_number(a) != is_number(b) && (is_vector(a) || is_vector(b))) {
    const Value& vec = is_vector(a) ? a : b;
    const double k = is_number(a) ? a.number : b.number;
    Value r = each_number(vec, [k](double x) { return x * k; }, memory);
    if (r.kind == Value::Kind::Undef) refuse_operands(BinaryOp::Times, a, b, at, kAccepted);
    r.loc = a.loc;
    return r;
  }
  // Two vectors of numbers: the dot product. (OpenSCAD's matrix products are
  // not part of scene files.)
  if (is_vector(a) && is_vector(b) && !a.items.empty() && a.items.size() == b.items.size()) {
    double dot = 0;
    for (size_t i = 0; i < a.items.size(); ++i) {
      if (!is_number(a.items[i]) || !is_number(b.items[i])) {
        refuse_operands(BinaryOp::Times, a, b, at, kAccepted);
      }
      dot += a.items[i].number * b.items[i].number;
    }
    return number(dot, a.loc, memory);
  }
  refuse_operands(BinaryOp::Times, a, b, at, kAccepted);
}

Value divide(const Value& a, const Value& b, const Token& at, std::pmr::memory_resource* memory) {
  constexpr std::string_view kAccepted = "two numbers, or a number and a vector of numbers";
  if (is_number(a) && is_number(b)) return number(a.number / b.number, a.loc, memory);
  Value r(memory, a.loc);
  if (is_vector(a) && is_number(b)) {
    const double k = b.number;
    r = each_number(a, [k](double x) { return x / k; }, memory);
  } else if (is_number(a) && is_vector(b)) {
    const double k = a.number;
    r = each_number(b, [k](double x) { return k / x; }, memory);
  }
  if (r.kind == Value::Kind::Undef) refuse_operands(BinaryOp::Divide, a, b, at, kAccepted);
  r.loc = a.loc;
  return r;
}

// ---- built-in functions ----

struct Builtin {
  std::string_view name;
  Arity arity;
};

constexpr Builtin kBuiltins[] = {
    {"sin", {1, 1}},  {"cos", {1, 1}},   {"tan", {1, 1}},   {"asin", {1, 1}},  {"acos", {1, 1}},
    {"atan", {1, 1}}, {"atan2", {2, 2}}, {"abs", {1, 1}},   {"sign", {1, 1}},  {"sqrt", {1, 1}},
    {"pow", {2, 2}},  {"exp", {1, 1}},   {"ln", {1, 1}},    {"log", {1, 2}},   {"min", {1, -1}},
    {"max", {1, -1}}, {"floor", {1, 1}}, {"ceil", {1, 1}},  {"round", {1, 1}}, {"lookup", {2, 2}},
};

[[noreturn, gnu::noinline]] void refuse_argument(const Token& call, const Value& arg,
                                                 std::string_view expected) {
  throw SceneError(arg.loc, fmt::format("{}() needs {} here, got {}", call.text, expected,
                                        describe(arg)));
}

double number_arg(const Token& call, const Value& arg) {
  if (!is_number(arg)) refuse_argument(call, arg, "a number");
  return arg.number;
}

Value min_max(const Token& call, std::span<const Value> args, std::pmr::memory_resource* memory) {
  const bool is_min = call.text == "min";
  const auto better = [is_min](double x, double best) { return is_min ? x < best : x > best; };
  // One vector: its least (greatest) element.
  if (args.size() == 1 && is_vector(args[0])) {
    const Value& v = args[0];
    if (v.items.empty()) refuse_argument(call, v, "a number or a vector of numbers that is not empty");
    double best = number_arg(call, v.items[0]);
    for (const Value& e : v.items) {
      const double x = number_arg(call, e);
      if (better(x, best)) best = x;
    }
    return number(best, call.loc, memory);
  }
  double best = number_arg(call, args[0]);
  for (const Value& e : args.subspan(1)) {
    const double x = number_arg(call, e);
    if (better(x, best)) best = x;
  }
  return number(best, call.loc, memory);
}

// lookup(key, [[k, v], ...]): v linearly interpolated between the two
// entries whose keys surround `key`, clamped to the values at the least and
// greatest keys; entries need not be sorted (OpenSCAD's algorithm).
Value lookup(const Token& call, std::span<const Value> args, std::pmr::memory_resource* memory) {
  const double p = number_arg(call, args[0]);
  if (!std::isfinite(p)) refuse_argument(call, args[0], "a finite number");
  const Value& table = args[1];
  constexpr std::string_view kTable = "a vector of [key, value] pairs of numbers";
  if (!is_vector(table) || table.items.empty()) refuse_argument(call, table, kTable);
  const auto pair = [&](const Value& e, double& k, double& v) {
    if (!is_vector(e) || e.items.size() != 2 || !is_number(e.items[0]) || !is_number(e.items[1])) {
      refuse_argument(call, e, "a [key, value] pair of numbers");
    }
    k = e.items[0].number;
    v = e.items[1].number;
  };
  double low_p, low_v;
  pair(table.items[0], low_p, low_v);
  double high_p = low_p, high_v = low_v;
  for (size_t i = 1; i < table.items.size(); ++i) {
    double this_p, this_v;
    pair(table.items[i], this_p, this_v);
    if (this_p <= p && (this_p > low_p || low_p > p)) {
      low_p = this_p;
      low_v = this_v;
    }
    if (this_p >= p && (this_p < high_p || high_p < p)) {
      high_p = this_p;
      high_v = this_v;
    }
  }
  if (p <= low_p) return number(high_v, call.loc, memory);
  if (p >= high_p) return number(low_v, call.loc, memory);
  const double f = (p - low_p) / (high_p - low_p);
  return number(high_v * f + low_v * (1 - f), call.loc, memory);
}

double reduce_degrees(double x, double turn) {
  return x - turn * std::floor(x / turn);
}

}  // namespace

double sin_degrees(double x) {
  if (!(x < 360.0 && x >= 0.0)) {
    if (!(x < kTrigHuge && x > -kTrigHuge)) return std::numeric_limits<double>::quiet_NaN();
    x = reduce_degrees(x, 360.0);
  }
  const bool oppose = x >= 180.0;
  if (oppose) x -= 180.0;
  if (x > 90.0) x = 180.0 - x;
  if (x < 45.0) {
    x = x == 30.0 ? 0.5 : std::sin(deg2rad(x));
  } else if (x == 45.0) {
    x = kSqrt1_2;
  } else if (x == 60.0) {
    x = kSqrt3_4;
  } else {
    x = std::cos(deg2rad(90.0 - x));
  }
  return oppose ? -x : x;
}

double cos_degrees(double x) {
  if (!(x < 360.0 && x >= 0.0)) {
    if (!(x < kTrigHuge && x > -kTrigHuge)) return std::numeric_limits<double>::quiet_NaN();
    x = reduce_degrees(x, 360.0);
  }
  bool oppose = x >= 180.0;
  if (oppose) x -= 180.0;
  if (x > 90.0) {
    x = 180.0 - x;
    oppose = !oppose;
  }
  if (x > 45.0) {
    x = x == 60.0 ? 0.5 : std::sin(deg2rad(90.0 - x));
  } else if (x == 45.0) {
    x = kSqrt1_2;
  } else if (x == 30.0) {
    x = kSqrt3_4;
  } else {
    x = std::cos(deg2rad(x));
  }
  return oppose ? -x : x;
}

double tan_degrees(double x) {
  if (!(x < kTrigHuge && x > -kTrigHuge)) return std::numeric_limits<double>::quiet_NaN();
  // OpenSCAD keeps the count of half turns in an int; within kTrigHuge it fits
  // a 64-bit one, and only its parity matters.
  const auto cycles = static_cast<long long>(std::floor(x / 180.0));
  if (!(x < 180.0 && x >= 0.0)) x -= 180.0 * static_cast<double>(cycles);
  const bool oppose = x > 90.0;
  if (oppose) x = 180.0 - x;
  const bool even = cycles % 2 == 0;
  if (x == 0.0) {
    x = even ? 0.0 : -0.0;
  } else if (x == 30.0) {
    x = kSqrt1_3;
  } else if (x == 45.0) {
    x = 1.0;
  } else if (x == 60.0) {
    x = kSqrt3;
  } else if (x == 90.0) {
    x = even ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
  } else {
    x = std::tan(deg2rad(x));
  }
  return oppose ? -x : x;
}

// The inverse functions give a whole number of degrees when the function of
// that whole number gives back x exactly (asin(0.5) is 30, not
// 30.000000000000004), and atan2 when it is within 3e-14 of one.
double asin_degrees(double x) {
  const double degrees = rad2deg(std::asin(x)), whole = std::round(degrees);
  return sin_degrees(whole) == x ? whole : degrees;
}

double acos_degrees(double x) {
  const double degrees = rad2deg(std::acos(x)), whole = std::round(degrees);
  return cos_degrees(whole) == x ? whole : degrees;
}

double atan_degrees(double x) {
  const double degrees = rad2deg(std::atan(x)), whole = std::round(degrees);
  return tan_degrees(whole) == x ? whole : degrees;
}

double atan2_degrees(double y, double x) {
  const double degrees = rad2deg(std::atan2(y, x)), whole = std::round(degrees);
  return std::fabs(degrees - whole) < 3.0e-14 ? whole : degrees;
}

bool truthy(const Value& v) {
  switch (v.kind) {
    case Value::Kind::Undef: return false;
    case Value::Kind::Bool: return v.boolean;
    case Value::Kind::Number: return v.number != 0;
    case Value::Kind::String: return !v.string.empty();
    case Value::Kind::Vector: return !v.items.empty();
  }
  return false;
}

Value apply_binary(BinaryOp op, const Value& a, const Value& b, const Token& op_token,
                   std::pmr::memory_resource* memory) {
  switch (op) {
    case BinaryOp::Or: return boolean(truthy(a) || truthy(b), a.loc, memory);
    case BinaryOp::And: return boolean(truthy(a) && truthy(b), a.loc, memory);
    case BinaryOp::Equal: return boolean(equal(a, b), a.loc, memory);
    case BinaryOp::NotEqual: return boolean(!equal(a, b), a.loc, memory);
    case BinaryOp::Less:
    case BinaryOp::LessEqual:
    case BinaryOp::Greater:
    case BinaryOp::GreaterEqual: return boolean(compare(op, a, b, op_token), a.loc, memory);
    case BinaryOp::Plus:
    case BinaryOp::Minus: return add(op, a, b, op_token, memory);
    case BinaryOp::Times: return multiply(a, b, op_token, memory);
    case BinaryOp::Divide: return divide(a, b, op_token, memory);
    case BinaryOp::Modulo:
      if (!is_number(a) || !is_number(b)) refuse_operands(op, a, b, op_token, "two numbers");
      return number(std::fmod(a.number, b.number), a.loc, memory);
    case BinaryOp::Power:
      if (!is_number(a) || !is_number(b)) refuse_operands(op, a, b, op_token, "two numbers");
      return number(std::pow(a.number, b.number), a.loc, memory);
  }
  refuse_operands(op, a, b, op_token, "?");
}

Value negate(const Value& v, const Token& op_token, std::pmr::memory_resource* memory) {
  if (is_number(v) || is_vector(v)) {
    Value r = each_number(v, [](double x) { return -x; }, memory);
    if (r.kind != Value::Kind::Undef) {
      r.loc = op_token.loc;
      return r;
    }
  }
  throw SceneError(op_token.loc,
                   fmt::format("unary '-' takes a number or a vector of numbers, got {}", describe(v)));
}

Arity function_arity(std::string_view name) {
  for (const Builtin& b : kBuiltins) {
    if (b.name == name) return b.arity;
  }
  return Arity{};
}

std::string_view function_names() {
  return "sin, cos, tan, asin, acos, atan, atan2, abs, sign, sqrt, pow, exp, ln, log, min, max, "
         "floor, ceil, round, lookup";
}

Value call_function(const Token& call, std::span<const Value> args,
                    std::pmr::memory_resource* memory) {
  const std::string_view f = call.text;
  if (f == "min" || f == "max") return min_max(call, args, memory);
  if (f == "lookup") return lookup(call, args, memory);
  if (f == "atan2") {
    return number(atan2_degrees(number_arg(call, args[0]), number_arg(call, args[1])), call.loc,
                  memory);
  }
  if (f == "pow") {
    return number(std::pow(number_arg(call, args[0]), number_arg(call, args[1])), call.loc, memory);
  }
  if (f == "log") {
    // log(x) is log base 10 computed as ln(x) / ln(10), and log(b, x) base b:
    // OpenSCAD's formula, whose last bit differs from log10's.
    double base = 10.0, x = number_arg(call, args[0]);
    if (args.size() == 2) {
      base = x;
      x = number_arg(call, args[1]);
    }
    return number(std::log(x) / std::log(base), call.loc, memory);
  }
  const double x = number_arg(call, args[0]);
  double r = 0;
  if (f == "sin") r = sin_degrees(x);
  else if (f == "cos") r = cos_degrees(x);
  else if (f == "tan") r = tan_degrees(x);
  else if (f == "asin") r = asin_degrees(x);
  else if (f == "acos") r = acos_degrees(x);
  else if (f == "atan") r = atan_degrees(x);
  else if (f == "abs") r = std::fabs(x);
  else if (f == "sign") r = x < 0 ? -1.0 : (x > 0 ? 1.0 : 0.0);
  else if (f == "sqrt") r = std::sqrt(x);
  else if (f == "exp") r = std::exp(x);
  else if (f == "ln") r = std::log(x);
  else if (f == "floor") r = std::floor(x);
  else if (f == "ceil") r = std::ceil(x);
  else r = std::round(x);  // "round": halves away from zero, as C's round
  return number(r, call.loc, memory);
}

}  // namespace capsim::scene_file
