// Reading JSON values with errors that name the file and the JSON path (json_field.h).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "base/errors.h"
#include "base/json_field.h"

namespace sdog {
namespace {

using nlohmann::json;

TEST(JsonField, ReadsValuesAndNamesThePathOfWhatIsWrong) {
  const json j = json::parse(R"({"a": {"b": [1, 2.5, "x"]}, "n": 3, "t": true})");
  const Field root(j, "$", "f.json");
  EXPECT_EQ(root["n"].integer(0), 3);
  EXPECT_EQ(root["a"]["b"][1].number(), 2.5);
  EXPECT_TRUE(root["t"].boolean());
  EXPECT_EQ(root["a"]["b"].array_size(), 3u);
  EXPECT_EQ(root["a"]["b"][2].where(), "f.json: $.a.b[2]");
  auto message = [](auto&& read) -> std::string {
    try {
      read();
    } catch (const InputError& e) {
      return e.what();
    }
    return "accepted";
  };
  EXPECT_EQ(message([&] { root["a"]["b"][2].number(); }), "f.json: $.a.b[2]: expected a number");
  EXPECT_EQ(message([&] { root["n"].integer(5); }), "f.json: $.n: expected an integer >= 5, got 3");
  EXPECT_EQ(message([&] { root["a"]["b"].vector<2>(); }),
            "f.json: $.a.b: expected an array of 2 numbers");
  EXPECT_EQ(message([&] { root["t"].text(); }), "f.json: $.t: expected a string");
  EXPECT_EQ(message([&] {
              root.expect_object({"a", "n"});
            }),
            "f.json: $.t: unknown key (known: a, n)");
}

}  // namespace
}  // namespace sdog
