#include "cosim/config/selection_table.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>

#include "cosim/config/document.hpp"
#include "input_error.hpp"

namespace cosim::config {
namespace {

using cosim::testing::input_error_from;

struct Shape {
  virtual ~Shape() = default;
  virtual double area() const = 0;
};
struct Square : Shape {
  explicit Square(double length) : side(length) {}
  double area() const override { return side * side; }
  double side;
};

SelectionTable<Shape> shapes() {
  SelectionTable<Shape> table("shape", "shapes.<name> with type: {}");
  Schema square = Schema::object("A square.");
  square.required("type", Schema::string(), "Model name.")
      .required("side", Schema::number().positive().unit("m"), "Side length.");
  table.add("square", square,
            [](const Node& n) { return std::make_unique<Square>(n["side"].as<double>()); });
  return table;
}

Node root_of(const std::string& text) {
  return Document::load_string(text, "shapes.yaml").root();
}

TEST(SelectionTable, MakesTheModelNamedByType) {
  const auto shape = shapes().make(root_of("{type: square, side: 2.0}"));
  EXPECT_DOUBLE_EQ(shape->area(), 4.0);
}

TEST(SelectionTable, ValidatesAgainstTheModelsSchemaBeforeMaking) {
  const InputError error =
      input_error_from([] { (void)shapes().make(root_of("{type: square, side: -1}")); });
  EXPECT_NE(std::string(error.what()).find("side"), std::string::npos);
}

TEST(SelectionTable, RefusesAnUnknownTypeWithASuggestionAtItsKey) {
  const InputError error =
      input_error_from([] { (void)shapes().make(root_of("{type: sqare, side: 1}")); });
  const std::string text = error.what();
  EXPECT_NE(text.find("shapes.yaml:1:"), std::string::npos) << text;
  EXPECT_NE(text.find("unknown shape 'sqare'"), std::string::npos) << text;
  EXPECT_NE(text.find("square"), std::string::npos) << text;
}

TEST(SelectionTable, RefusesAScalarWhereAMappingBelongs) {
  const InputError error = input_error_from([] { (void)shapes().make(root_of("square")); });
  EXPECT_NE(std::string(error.what()).find("expected a mapping"), std::string::npos);
}

TEST(SelectionTable, RefusesATypeRegisteredTwice) {
  SelectionTable<Shape> table = shapes();
  EXPECT_THROW(table.add("square", Schema::object(), nullptr), std::logic_error);
  EXPECT_EQ(table.types(), std::vector<std::string>{"square"});
}

TEST(SelectionTable, HelpListsEveryModelUnderItsTitle) {
  EXPECT_NE(shapes().help().find("shapes.<name> with type: square"), std::string::npos);
}

}  // namespace
}  // namespace cosim::config
