// The study parser: a parameter's value put into scene keys ($b, ${expression}), the numbers
// the plots put on their axis, the names runs read by, and every mistake refused at its line.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/io/scene_error.hpp"
#include "core/io/study_expression.hpp"
#include "core/io/study_yaml.hpp"

namespace fp {
namespace {

const std::string kHead = "scene: base.yaml\nparameters:\n";

std::vector<std::string> changes(const StudyLevel& level) {
  std::vector<std::string> out;
  for (const auto& o : level.overrides) out.push_back(o.key + "=" + o.value);
  return out;
}

void expect_refused(const std::string& text, int line, const std::string& words) {
  try {
    parse_study(text, "s.yaml");
    ADD_FAILURE() << "accepted:\n" << text;
  } catch (const SceneError& e) {
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(StudyExpression, ArithmeticAsWritten) {
  EXPECT_EQ(evaluate_expression("2 * r", "r", 0.25), 0.5);
  EXPECT_EQ(evaluate_expression("1 + 2 * 3", "x", 0), 7);
  EXPECT_EQ(evaluate_expression("(1 + 2) * 3", "x", 0), 9);
  EXPECT_EQ(evaluate_expression("2 ^ 3 ^ 2", "x", 0), 512);  // right-associative
  EXPECT_EQ(evaluate_expression("-2 ^ 2", "x", 0), -4);
  EXPECT_EQ(evaluate_expression("2 ^ -1", "x", 0), 0.5);
  EXPECT_EQ(evaluate_expression("8 / 2 / 2", "x", 0), 2);   // left-associative
  EXPECT_EQ(evaluate_expression("1 - 2 - 3", "x", 0), -4);
  EXPECT_EQ(evaluate_expression("sqrt(b) * 3", "b", 4), 6);
  EXPECT_EQ(evaluate_expression("cbrt(27)+abs(-1)", "b", 4), 4);
  EXPECT_DOUBLE_EQ(evaluate_expression("pi * r^2", "r", 2), 4 * std::numbers::pi);
  EXPECT_EQ(evaluate_expression("1e-3 * ratio", "ratio", 7), 7e-3);
}

TEST(StudyExpression, MistakesSayWhere) {
  const auto message = [](const std::string& text) {
    try {
      evaluate_expression(text, "b", 1);
    } catch (const ExpressionError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message("2 * c").find("unknown name 'c'"), std::string::npos) << message("2 * c");
  EXPECT_NE(message("2 *").find("at character 4"), std::string::npos) << message("2 *");
  EXPECT_NE(message("(b").find("')' expected"), std::string::npos);
  EXPECT_NE(message("b b").find("unexpected 'b'"), std::string::npos);
  EXPECT_NE(message("1 / (b - 1)").find("not a finite number where b = 1"), std::string::npos) << message("1 / (b - 1)");
  EXPECT_NE(message("sqrt(-b)").find("not a finite number"), std::string::npos);
  EXPECT_NE(message("sqrt b").find("'(' expected after sqrt"), std::string::npos);
}

TEST(StudyExpression, NumbersReadBackExactly) {
  for (const double x : {0.1, 1.0 / 3.0, 1e-300, 2.0, -7.5e22, 0x1.fffffffffffffp+1023}) {
    const std::string t = shortest_number_text(x);
    EXPECT_EQ(std::stod(t), x) << t;
  }
  EXPECT_EQ(shortest_number_text(2), "2");
  EXPECT_EQ(shortest_number_text(0.1), "0.1");
}

TEST(StudyYaml, AValueGoesIntoAListAndAComputedNumber) {
  const StudySpec s = parse_study(kHead +
                                      "  - name: b\n"
                                      "    values: [0.5, 0.8]\n"
                                      "    set:\n"
                                      "      'particles[0].axes': [1, $b, $b]\n"
                                      "      particles.radius: {distribution: uniform, min: 0.5, max: '${0.5 / b}'}\n",
                                  "s.yaml");
  ASSERT_EQ(s.parameters.size(), 1u);
  const StudyParameter& p = s.parameters[0];
  ASSERT_EQ(p.levels.size(), 2u);
  EXPECT_EQ(changes(p.levels[0]), (std::vector<std::string>{"particles[0].axes=[1, 0.5, 0.5]",
                                                            "particles.radius={distribution: uniform, min: 0.5, max: 1}"}));
  EXPECT_EQ(changes(p.levels[1]), (std::vector<std::string>{"particles[0].axes=[1, 0.8, 0.8]",
                                                            "particles.radius={distribution: uniform, min: 0.5, max: 0.625}"}));
  EXPECT_TRUE(p.numeric);
  EXPECT_EQ(p.axis, (std::vector<double>{0.5, 0.8}));
  EXPECT_EQ(p.levels[0].label, "0.5");
  EXPECT_EQ(p.levels[1].name_part, "0.8");
  // The change remembers where its template was written, for messages about the run.
  EXPECT_EQ(p.levels[0].overrides[0].origin.line, 6);
}

TEST(StudyYaml, AWholeValueMayBeAnyYamlAndTextTakesItsText) {
  const StudySpec s = parse_study(kHead +
                                      "  - name: shape\n"
                                      "    values: [cube, octahedron]\n"
                                      "    set: {'particles[0].preset': $shape, scene: 'scenes/$shape-$$.yaml'}\n",
                                  "dir/s.yaml");
  const StudyParameter& p = s.parameters[0];
  EXPECT_EQ(changes(p.levels[0]), (std::vector<std::string>{"particles[0].preset=cube"}));
  EXPECT_EQ(p.levels[1].scene_path, "dir/scenes/octahedron-$.yaml");
  EXPECT_FALSE(p.numeric);
  EXPECT_EQ(p.name_part, "shape");
}

TEST(StudyYaml, ListsOfNumbersGetTheNumberTheyVaryIn) {
  const StudySpec s = parse_study(kHead +
                                      "  - key: particles[0].axes\n"
                                      "    values: [[1, 0.5, 0.5], [1, 0.7, 0.7], [1, 0.9, 0.9]]\n"
                                      "  - key: container.max\n"
                                      "    values: [[2, 1, 1], [1, 2, 1]]\n"
                                      "  - key: packer.radius_pool\n"
                                      "    values: [1, 4]\n",
                                  "s.yaml");
  const StudyParameter& axes = s.parameters[0];
  EXPECT_EQ(axes.axis, (std::vector<double>{0.5, 0.7, 0.9}));
  EXPECT_EQ(axes.axis_label, "particles[0].axes [1, x, x]");
  EXPECT_EQ(axes.name_part, "axes");
  EXPECT_EQ(axes.levels[1].name_part, "1_0.7_0.7");
  // Two entries that do not vary together have no single number: the axis lists the values.
  EXPECT_FALSE(s.parameters[1].numeric);
  EXPECT_TRUE(s.parameters[1].axis.empty());
  EXPECT_EQ(s.parameters[1].name_part, "max");
  EXPECT_EQ(s.parameters[2].axis, (std::vector<double>{1, 4}));
  EXPECT_EQ(s.parameters[2].axis_label, "packer.radius_pool");
}

TEST(StudyYaml, KeysEndingAlikeKeepTheirWholeNamesInRunNames) {
  const StudySpec s = parse_study(kHead +
                                      "  - {key: particles.radius.max, values: [1, 2]}\n"
                                      "  - {key: container.max, values: [[1, 1, 1]]}\n"
                                      "  - {key: particles.radius.min, values: [0.5]}\n",
                                  "s.yaml");
  EXPECT_EQ(s.parameters[0].name_part, "particles.radius.max");
  EXPECT_EQ(s.parameters[1].name_part, "container.max");
  EXPECT_EQ(s.parameters[2].name_part, "min");
}

TEST(StudyYaml, BindingMistakesAreRefusedAtTheirLine) {
  // Not its own value.
  expect_refused(kHead + "  - name: b\n    values: [1]\n    set: {packer.radius_pool: $c}\n", 5, "'$c' is not this parameter's value");
  // No use of the value: every run the same.
  expect_refused(kHead + "  - name: b\n    values: [1, 2]\n    set: {packer.radius_pool: 3}\n", 5, "no value of 'set' uses $b");
  // A name that $name cannot write.
  expect_refused(kHead + "  - name: radius max\n    values: [1]\n    set: {x: $b}\n", 3, "letters, digits and _");
  // key and set at once.
  expect_refused(kHead + "  - {name: b, key: packer.front, values: [1], set: {x: $b}}\n", 3, "not both");
  // An expression on a value that is not a number; a bad expression; one that is not finite.
  expect_refused(kHead + "  - name: b\n    values: [fifo]\n    set: {packer.radius_pool: '${2 * b}'}\n", 5, "computes with a number");
  expect_refused(kHead + "  - name: b\n    values: [1]\n    set: {packer.radius_pool: '${2 * }'}\n", 5, "at character");
  expect_refused(kHead + "  - name: b\n    values: [0, 1]\n    set: {packer.radius_pool: '${1 / b}'}\n", 5,
                 "not a finite number where b = 0");
  // A list value inside text; a lone '$'; an unclosed ${.
  expect_refused(kHead + "  - name: b\n    values: [[1, 2]]\n    set: {scene: 'x-$b.yaml'}\n", 5, "needs a single value");
  expect_refused(kHead + "  - name: b\n    values: [1]\n    set: {scene: 'x-$-$b.yaml'}\n", 5, "write $$ for a dollar sign");
  expect_refused(kHead + "  - name: b\n    values: [1]\n    set: {packer.radius_pool: '${b'}\n", 5, "without its '}'");
  // A key that is not a scene key.
  expect_refused(kHead + "  - name: b\n    values: [1]\n    set: {'packer..x': $b}\n", 5, "not a scene key");
}

}  // namespace
}  // namespace fp
