// Tests of expressions in scene files: OpenSCAD 2021.01's precedence, its
// exact degree trigonometry, lookup, round, %, log, min and max, vectors,
// $t, the parts OpenSCAD does not evaluate, located errors and the nesting
// limit. Every expected value here is what OpenSCAD 2021.01 gives for the
// same expression (checked with echo() of the expression, or of `expr ==
// value` where echo's 6 digits cannot tell).

#include "capsim/scene/parser.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <string_view>

#include "capsim/scene/scene.h"

namespace capsim {
namespace {

const std::string kFile = "e.csg";

// The scene an expression is tried in: the expression starts line 2, column 1,
// as the x of the camera's eye (kept as given).
std::string scene_with(std::string_view expr) {
  return fmt::format("camera(eye = [\n{}, 1, 2]);\ncube();", expr);
}

double eval(std::string_view expr, double t = 0) {
  const Scene scene = parse_scene(scene_with(expr), kFile, {}, t);
  return scene.camera->eye.x;
}

// The expression is refused at line 2, column `col` with a message holding
// `fragment`.
::testing::AssertionResult RefusedAt(std::string_view expr, int col, std::string_view fragment,
                                     double t = 0) {
  try {
    parse_scene(scene_with(expr), kFile, {}, t);
  } catch (const SceneError& e) {
    if (e.loc().line != 2 || e.loc().col != col || e.message().find(fragment) == std::string::npos) {
      return ::testing::AssertionFailure() << "expected 2:" << col << " with \"" << fragment
                                           << "\", got: " << e.what();
    }
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure() << "parsed without error";
}

TEST(SceneExpression, PrecedenceAndAssociativityAreOpenScads) {
  EXPECT_EQ(eval("1 + 2 * 3"), 7);
  EXPECT_EQ(eval("(1 + 2) * 3"), 9);
  EXPECT_EQ(eval("10 - 4 - 3"), 3);    // left-associative
  EXPECT_EQ(eval("2 * 3 % 4"), 2);     // * / % one level, left to right
  EXPECT_EQ(eval("-2^2"), -4);         // ^ binds tighter than a sign on its left
  EXPECT_EQ(eval("2^3^2"), 512);       // right-associative
  EXPECT_EQ(eval("2^-1"), 0.5);        // a sign may start the exponent
  EXPECT_EQ(eval("-2^-2"), -0.25);
  EXPECT_EQ(eval("2 ^ 2 * 3"), 12);
  EXPECT_EQ(eval("- - 3"), 3);
  EXPECT_EQ(eval("+-+3"), -3);
  EXPECT_EQ(eval("1 < 2 == true ? 5 : 6"), 5);              // comparison before equality
  EXPECT_EQ(eval("1 + 1 == 2 && 3 > 2 || 0 ? 7 : 8"), 7);
  EXPECT_EQ(eval("0 || 0 && 1 ? 1 : 2"), 2);                // && before ||
  EXPECT_EQ(eval("false ? 1 : false ? 2 : 3"), 3);          // ? : nests to the right
  EXPECT_EQ(eval("!0 ? 1 : 2"), 1);
  EXPECT_EQ(eval("(! 1 == false) ? 1 : 2"), 1);             // ! before ==
  EXPECT_EQ(eval("1 != 2 && 2 >= 2 && 2 <= 2 && !(3 < 2) ? 1 : 0"), 1);
}

TEST(SceneExpression, DollarTIsTheAnimationTime) {
  EXPECT_EQ(eval("$t"), 0);
  EXPECT_EQ(eval("$t * 360", 0.25), 90);
  EXPECT_EQ(eval("PI"), 3.14159265358979323846);
}

TEST(SceneExpression, TrigonometryIsExactAtMultiplesOf30And45Degrees) {
  EXPECT_EQ(eval("sin(30)"), 0.5);
  EXPECT_EQ(eval("sin(45)"), std::sqrt(2.0) / 2);
  EXPECT_EQ(eval("sin(60)"), std::sqrt(3.0) / 2);
  EXPECT_EQ(eval("sin(90)"), 1);
  EXPECT_EQ(eval("sin(180)"), 0);  // std::sin(M_PI) is 1.2e-16
  EXPECT_EQ(eval("sin(210)"), -0.5);
  EXPECT_EQ(eval("sin(-30)"), -0.5);
  EXPECT_EQ(eval("sin(390)"), 0.5);
  EXPECT_EQ(eval("cos(60)"), 0.5);
  EXPECT_EQ(eval("cos(90)"), 0);
  EXPECT_EQ(eval("cos(120)"), -0.5);
  EXPECT_EQ(eval("cos(270)"), 0);
  EXPECT_EQ(eval("tan(45)"), 1);
  EXPECT_EQ(eval("tan(135)"), -1);
  EXPECT_EQ(eval("tan(60)"), std::sqrt(3.0));
  EXPECT_EQ(eval("tan(30)"), std::sqrt(3.0) / 3);
  EXPECT_EQ(eval("sin(30) * sin(30)"), 0.25);
  // The inverse functions snap to whole degrees when exact.
  EXPECT_EQ(eval("asin(0.5)"), 30);  // std::asin gives 30.000000000000004 degrees
  EXPECT_EQ(eval("asin(1)"), 90);
  EXPECT_EQ(eval("acos(0.5)"), 60);
  EXPECT_EQ(eval("atan(1)"), 45);
  EXPECT_EQ(eval("atan2(1, 1)"), 45);
  EXPECT_EQ(eval("atan2(-1, 0)"), -90);
  // Elsewhere, the plain functions of the angle in radians.
  EXPECT_DOUBLE_EQ(eval("sin(10)"), std::sin(10 * 0.017453292519943295769));
}

TEST(SceneExpression, LookupInterpolatesAndClamps) {
  const std::string table = "[[0, -2], [0.5, 1], [1, 2]]";
  EXPECT_EQ(eval("lookup(0.25, " + table + ")"), -0.5);
  EXPECT_EQ(eval("lookup(0.5, " + table + ")"), 1);
  EXPECT_EQ(eval("lookup(-1, " + table + ")"), -2);  // below the least key
  EXPECT_EQ(eval("lookup(5, " + table + ")"), 2);    // above the greatest
  EXPECT_EQ(eval("lookup(0.75, [[1, 2], [0, -2], [0.5, 1]])"), 1.5);  // keys in any order
  EXPECT_EQ(eval("lookup($t, " + table + ")", 0.75), 1.5);
}

TEST(SceneExpression, RoundModuloLogMinMax) {
  EXPECT_EQ(eval("round(2.5)"), 3);  // halves away from zero
  EXPECT_EQ(eval("round(-2.5)"), -3);
  EXPECT_EQ(eval("round(-0.5)"), -1);
  EXPECT_EQ(eval("round(0.49999999999999994)"), 0);
  EXPECT_EQ(eval("-7 % 3"), -1);  // fmod: the sign of the dividend
  EXPECT_EQ(eval("7 % -3"), 1);
  EXPECT_EQ(eval("5.5 % 2"), 1.5);
  EXPECT_EQ(eval("log(1000)"), 2.9999999999999996);  // ln(x) / ln(10), as OpenSCAD
  EXPECT_EQ(eval("log(100)"), 2);
  EXPECT_EQ(eval("log(2, 8)"), 3);  // base first
  EXPECT_EQ(eval("ln(1)"), 0);
  EXPECT_EQ(eval("min(3, 1, 2)"), 1);
  EXPECT_EQ(eval("max([4, 9, 2])"), 9);
  EXPECT_EQ(eval("min([5])"), 5);
  EXPECT_EQ(eval("sign(-3) + abs(-2) + floor(-1.5) + ceil(-1.5)"), -2);
  EXPECT_EQ(eval("sqrt(16) + exp(0) + pow(2, 10)"), 1029);
}

TEST(SceneExpression, VectorArithmetic) {
  const auto eye = [](std::string_view expr) {
    return parse_scene(fmt::format("camera(eye = {});\ncube();", expr), kFile).camera->eye;
  };
  EXPECT_EQ(eye("[1, 0.5, 1] * 2"), glm::dvec3(2, 1, 2));
  EXPECT_EQ(eye("2 * [1, 0.5, 1] + [0, 0, 1]"), glm::dvec3(2, 1, 3));
  EXPECT_EQ(eye("[2, 4, 6] / 2 - [1, 1, 1]"), glm::dvec3(0, 1, 2));
  EXPECT_EQ(eye("-[1, 2, 3]"), glm::dvec3(-1, -2, -3));
  EXPECT_EQ(eye("[1, 2, 3, 4] + [1, 1, 1]"), glm::dvec3(2, 3, 4));  // the shorter length
  EXPECT_EQ(eval("[1, 2, 3] * [1, 1, 1]"), 6);                      // dot product
  EXPECT_EQ(eval("[1, 2] == [1, 2] && [1] != [1, 2] ? 1 : 0"), 1);
}

TEST(SceneExpression, WhatOpenScadDoesNotEvaluateIsOnlyChecked) {
  EXPECT_EQ(eval("$t > 0 ? 1 / $t : 0"), 0);  // 1 / 0 is never computed
  EXPECT_EQ(eval("$t > 0 ? 1 / $t : 0", 0.5), 2);
  EXPECT_EQ(eval("(true || sqrt(-1) > [1]) ? 1 : 2"), 1);
  EXPECT_EQ(eval("(false && 1 + \"a\") ? 1 : 2"), 2);
  // Names and argument counts are checked even there.
  EXPECT_TRUE(RefusedAt("true ? 1 : son(2)", 12, "unknown function 'son' (did you mean 'sin'?)"));
  EXPECT_TRUE(RefusedAt("false && pow(2)", 10, "pow() takes 2 arguments, got 1"));
}

TEST(SceneExpression, ErrorsAreLocated) {
  EXPECT_TRUE(RefusedAt("1 + foo(2)", 5, "unknown function 'foo'; supported: sin, cos"));
  EXPECT_TRUE(RefusedAt("2 * x", 5, "unknown variable 'x': expressions may use only $t"));
  EXPECT_TRUE(RefusedAt("$fn", 1, "unknown variable '$fn'"));
  EXPECT_TRUE(RefusedAt("sin(1, 2)", 1, "sin() takes 1 argument, got 2"));
  EXPECT_TRUE(RefusedAt("log()", 1, "log() takes 1 or 2 arguments, got 0"));
  EXPECT_TRUE(RefusedAt("max()", 1, "max() takes at least 1 arguments, got 0"));
  EXPECT_TRUE(RefusedAt("sin([1])", 5, "sin() needs a number here, got a vector of 1 element"));
  EXPECT_TRUE(RefusedAt("min(1, \"a\")", 8, "min() needs a number here, got a string"));
  EXPECT_TRUE(RefusedAt("min([])", 5, "got a vector of 0 elements"));
  EXPECT_TRUE(RefusedAt("lookup(1, [[0, 1], [2]])", 20, "lookup() needs a [key, value] pair"));
  EXPECT_TRUE(RefusedAt("1 + \"a\"", 3, "operator '+' takes two numbers or two vectors, got a "
                                        "number and a string"));
  EXPECT_TRUE(RefusedAt("[1] < [2] ? 1 : 0", 5, "operator '<' takes two numbers"));
  EXPECT_TRUE(RefusedAt("true % 2", 6, "operator '%' takes two numbers"));
  EXPECT_TRUE(RefusedAt("-\"a\"", 1, "unary '-' takes a number"));
  EXPECT_TRUE(RefusedAt("2 * (1 / 0)", 1, "the expression gives inf, not a finite number"));
  EXPECT_EQ(eval("min(1 / 0, 2)"), 2);  // infinite on the way is fine
  EXPECT_TRUE(RefusedAt("tan(90)", 1, "gives inf"));
  EXPECT_TRUE(RefusedAt("sqrt(-1)", 1, "gives nan"));
  EXPECT_TRUE(RefusedAt("1 ? 2 3", 7, "expected ':' of the '?' at 2:3, got number 3"));
  EXPECT_TRUE(RefusedAt("(1 + 2", 7, "expected ')' closing the '(' at 2:1"));
  EXPECT_TRUE(RefusedAt("sin(x = 1)", 5, "named arguments are not supported in function calls"));
  EXPECT_TRUE(RefusedAt("let(a = 1) a", 1, "'let' is not supported in scene-file expressions"));
  EXPECT_TRUE(RefusedAt("[for (i = [1:3]) i]", 2, "'for' is not supported"));
  EXPECT_TRUE(RefusedAt("[1, 2][0]", 7, "indexing a value"));
  EXPECT_TRUE(RefusedAt("PI.x", 3, "member access"));
  EXPECT_TRUE(RefusedAt("(1)(2)", 4, "only the built-in functions can be called"));
  EXPECT_TRUE(RefusedAt("1 +", 4, "expected a value, got ','"));
  EXPECT_TRUE(RefusedAt("1 | 0", 3, "expected ',' or ']', got '|'"));  // || and && only
  EXPECT_TRUE(RefusedAt("1 = 0", 3, "expected ',' or ']', got '='"));
}

// Expressions nest within the parser's one nesting limit, and what does not
// nest (long chains of operators or signs) takes no stack per operator.
TEST(SceneExpression, NestingIsBoundedAndChainsAreNot) {
  const auto nested = [](int levels) {
    return fmt::format("sphere(r = {}1{});", std::string(levels, '('), std::string(levels, ')'));
  };
  EXPECT_NO_THROW(parse_scene(nested(999), kFile));
  try {
    parse_scene(nested(1001), kFile);
    ADD_FAILURE() << "parsed without error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.loc().col, 12 + 1000);  // the '(' that opens level 1001
    EXPECT_NE(e.message().find("nesting deeper than 1000 levels"), std::string::npos) << e.what();
  }
  std::string powers = "sphere(r = 1";
  for (int i = 0; i < 1001; ++i) powers += "^1";
  EXPECT_THROW(parse_scene(powers + ");", kFile), SceneError);
  std::string sum = "sphere(r = 1";
  for (int i = 0; i < 200000; ++i) sum += "+1";
  EXPECT_EQ(parse_scene(sum + ");", kFile).primitives.size(), 1u);
  EXPECT_EQ(parse_scene("sphere(r = " + std::string(200000, '-') + "1);", kFile).primitives.size(), 1u);
}

}  // namespace
}  // namespace capsim
