// Scalars of the case: numbers and muParser expressions of x, y (case/format/expression.hpp).

#include "case/format/expression.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace fosls {
namespace {

Scalar expression(const std::string& text) { return Scalar{text, 0.0}; }

TEST(CompileScalar, ConstantIgnoresThePoint) {
  auto f = compile_scalar(Scalar{"", -2.5});
  EXPECT_EQ(f(0.0, 0.0), -2.5);
  EXPECT_EQ(f(3.0, -7.0), -2.5);
}

TEST(CompileScalar, EvaluatesXAndY) {
  auto f = compile_scalar(expression("0.4*(x-0.5)^2 + 2*y"));
  EXPECT_DOUBLE_EQ(f(0.5, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(f(1.0, 0.25), 0.4 * 0.25 + 0.5);
  EXPECT_DOUBLE_EQ(f(-1.0, 1.0), 0.4 * 2.25 + 2.0);
}

TEST(CompileScalar, KnowsConstantsAndFunctions) {
  auto f = compile_scalar(expression("sin(pi*x) + _pi - cos(0) + sqrt(abs(y)) + min(x, y)"));
  const double x = 0.25, y = -4.0;
  EXPECT_NEAR(f(x, y),
              std::sin(std::numbers::pi * x) + std::numbers::pi - 1.0 + 2.0 + std::min(x, y),
              1e-14);
  EXPECT_EQ(compile_scalar(expression("_pi"))(0, 0), std::numbers::pi);
  EXPECT_EQ(compile_scalar(expression("_e"))(0, 0), std::numbers::e);
  auto g = compile_scalar(expression("x < 0.5 ? 1 : 2"));
  EXPECT_EQ(g(0.0, 0.0), 1.0);
  EXPECT_EQ(g(0.7, 0.0), 2.0);
}

TEST(CompileScalar, CopiesShareOneParserAndStayValid) {
  ScalarFunction copy;
  {
    auto f = compile_scalar(expression("x*y"));
    copy = f;
  }
  EXPECT_DOUBLE_EQ(copy(3.0, 4.0), 12.0);
}

TEST(CompileScalar, BadExpressionThrowsInvalidArgument) {
  EXPECT_THROW(compile_scalar(expression("1 +")), std::invalid_argument);
  EXPECT_THROW(compile_scalar(expression("z")), std::invalid_argument);
}

TEST(CheckExpression, AcceptsGoodExpressions) {
  for (const char* text : {"0", "x", "0.02*(x-0.5)^2*4", "1 - sqrt(1 - x^2/4)", "exp(-x*x)",
                           "  y  ", "x < 0.5 ? 0 : 1", "sqrt(x)", "1e-3", "-x"})
    EXPECT_EQ(check_expression(text), std::nullopt) << text;
}

TEST(CheckExpression, RejectsSyntaxErrors) {
  for (const char* text : {"1 +", "(x", "x)", "2 * * x", "sin()", "x y", "1.2.3", "$"}) {
    auto reason = check_expression(text);
    ASSERT_TRUE(reason.has_value()) << text;
  }
  EXPECT_NE(check_expression("(x")->find("parse"), std::string::npos);
}

TEST(CheckExpression, NamesTheUnknownVariable) {
  auto reason = check_expression("x + z");
  ASSERT_TRUE(reason.has_value());
  EXPECT_NE(reason->find("\"z\""), std::string::npos) << *reason;
  EXPECT_NE(reason->find("unknown"), std::string::npos) << *reason;
  ASSERT_TRUE(check_expression("t").has_value());
  ASSERT_TRUE(check_expression("rand()").has_value());
}

TEST(CheckExpression, RejectsNonFiniteValues) {
  auto reason = check_expression("1/x");
  ASSERT_TRUE(reason.has_value());
  EXPECT_NE(reason->find("not finite"), std::string::npos) << *reason;
  EXPECT_TRUE(check_expression("ln(x)").has_value());
  EXPECT_TRUE(check_expression("sqrt(x - 2)").has_value());   // NaN at the sample points
  EXPECT_TRUE(check_expression("1/(y - 0.25)").has_value());  // infinite at (0.5, 0.25)
  EXPECT_TRUE(check_expression("1e308*1e308").has_value());
}

TEST(CheckExpression, RejectsEmptyLongAndControlText) {
  EXPECT_NE(check_expression("")->find("empty"), std::string::npos);
  EXPECT_NE(check_expression("   ")->find("empty"), std::string::npos);
  std::string sum = "0";
  while (sum.size() <= 1024) sum += "+x";
  auto reason = check_expression(sum);
  ASSERT_TRUE(reason.has_value());
  EXPECT_NE(reason->find("characters long"), std::string::npos) << *reason;
  EXPECT_EQ(check_expression(sum, sum.size()), std::nullopt);
  EXPECT_TRUE(check_expression(std::string("1\0+x", 4)).has_value());
  EXPECT_TRUE(check_expression("x\n+1").has_value());
  EXPECT_TRUE(check_expression("x\xc3\xa9").has_value());
}

TEST(CheckExpression, RejectsAssignmentAndSeveralValues) {
  EXPECT_NE(check_expression("x = 3")->find("assign"), std::string::npos);
  EXPECT_NE(check_expression("1, 2")->find("comma"), std::string::npos);
}

TEST(CheckExpression, DeepNestingIsHandled) {
  const std::string nested = std::string(400, '(') + "x" + std::string(400, ')');
  EXPECT_EQ(check_expression(nested), std::nullopt);
  EXPECT_TRUE(check_expression(std::string(1000, '(')).has_value());
  EXPECT_NO_THROW(check_expression(std::string(1000, '-') + "x"));
  EXPECT_NO_THROW(check_expression(std::string(300, '(') + std::string(300, ')')));
}

// Random printable text must give an answer, never a crash or an exception.
TEST(CheckExpression, RandomTextNeverThrows) {
  std::mt19937 rng(12345);
  const std::string alphabet = "xy0123456789.+-*/^()<>=!?:,_ esincoqrtpa&|";
  std::uniform_int_distribution<std::size_t> pick(0, alphabet.size() - 1), length(0, 40);
  int accepted = 0;
  for (int trial = 0; trial < 5000; ++trial) {
    std::string text;
    for (std::size_t n = length(rng); n > 0; --n) text += alphabet[pick(rng)];
    std::optional<std::string> reason;
    ASSERT_NO_THROW(reason = check_expression(text)) << text;
    if (!reason) {
      ++accepted;
      ASSERT_NO_THROW(compile_scalar(expression(text))(0.3, 0.6)) << text;
    }
  }
  EXPECT_GT(accepted, 0);
}

// The service checks cases on several threads at once; separate parsers must not interfere.
TEST(CheckExpression, ConcurrentUseGivesConsistentAnswers) {
  std::vector<std::thread> threads;
  std::vector<int> failures(4, 0);
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([t, &failures] {
      for (int i = 0; i < 300; ++i) {
        if (check_expression("sin(x)*y + " + std::to_string(t))) ++failures[t];
        if (!check_expression("x + q" + std::to_string(t))) ++failures[t];
        auto f = compile_scalar(expression("x*" + std::to_string(t + 1)));
        if (f(2.0, 0.0) != 2.0 * (t + 1)) ++failures[t];
      }
    });
  for (auto& th : threads) th.join();
  for (int f : failures) EXPECT_EQ(f, 0);
}

}  // namespace
}  // namespace fosls
