// Enum name tables (base/enum_names.h): printing, listing, parsing one name and a list of names.
#include "base/enum_names.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace sdog {
namespace {
enum class Fruit { kApple, kPear, kQuince };
}  // namespace

template <>
struct EnumNames<Fruit> {
  static constexpr const char* noun = "fruit";
  static constexpr EnumName<Fruit> rows[] = {
      {Fruit::kApple, "apple"}, {Fruit::kPear, "pear"}, {Fruit::kQuince, "quince"}};
};

namespace {

TEST(EnumNames, PrintsAndListsInTheEnumsOrder) {
  EXPECT_STREQ(enum_name(Fruit::kPear), "pear");
  EXPECT_EQ(enum_names<Fruit>(), (std::vector<std::string>{"apple", "pear", "quince"}));
  EXPECT_EQ(enum_values<Fruit>(),
            (std::vector<Fruit>{Fruit::kApple, Fruit::kPear, Fruit::kQuince}));
  EXPECT_EQ(known_names<Fruit>(), "apple, pear, quince");
}

TEST(EnumNames, ParsesANameOrSaysWhatIsKnown) {
  EXPECT_EQ(find_enum<Fruit>("quince"), Fruit::kQuince);
  EXPECT_FALSE(find_enum<Fruit>("Quince")) << "names are exact";
  EXPECT_EQ(parse_enum<Fruit>("apple"), Fruit::kApple);
  try {
    parse_enum<Fruit>("plum", "--fruit: ");
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_STREQ(e.what(), "--fruit: unknown fruit 'plum' (known: apple, pear, quince)");
  }
  EXPECT_THROW(parse_enum<Fruit>("plum", "basket.json: ", ErrorKind::kInput), InputError);
}

TEST(EnumNames, ParsesAListWithoutEmptyOrRepeatedNames) {
  EXPECT_EQ(parse_enum_list<Fruit>("pear,apple"),
            (std::vector<Fruit>{Fruit::kPear, Fruit::kApple}));
  const auto message = [](const std::string& text) {
    try {
      parse_enum_list<Fruit>(text, "--fruits: ");
    } catch (const UsageError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(""), "--fruits: no fruit given (known: apple, pear, quince)");
  EXPECT_EQ(message("pear,,apple"), "--fruits: unknown fruit '' (known: apple, pear, quince)");
  EXPECT_EQ(message("pear,"), "--fruits: unknown fruit '' (known: apple, pear, quince)");
  EXPECT_EQ(message("pear,pear"), "--fruits: fruit 'pear' is listed twice");
}

}  // namespace
}  // namespace sdog
