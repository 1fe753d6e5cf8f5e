#include "base/error.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace tactile {
namespace {

TEST(Error, TextShowsAsMuchOfTheLocationAsIsKnown) {
  EXPECT_EQ(Error("bad").text(), "bad");
  EXPECT_EQ(Error("a.db", "no such database").text(), "a.db: no such database");
  EXPECT_EQ(Error("r.csv", 12, 10, "column 'n3' (position 10): expected a number").text(),
            "r.csv:12: column 'n3' (position 10): expected a number");
  // A line without a file says nothing useful on its own and is left out.
  EXPECT_EQ(Error("", 3, 0, "odd").text(), "odd");
}

TEST(Result, HoldsAValueOrAnErrorNeverBoth) {
  Result<std::vector<int>> good(std::vector<int>{1, 2});
  ASSERT_TRUE(good.ok());
  EXPECT_TRUE(static_cast<bool>(good));
  EXPECT_EQ(good->size(), 2u);
  EXPECT_EQ(good.value()[1], 2);

  Result<std::vector<int>> bad(Error("f.csv", 4, 2, "broken"));
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().file, "f.csv");
  EXPECT_EQ(bad.error().line, 4u);
  EXPECT_EQ(bad.error().column, 2u);
  EXPECT_EQ(bad.errorText(), "f.csv:4: broken");

  auto failed = Result<int>::failure("no");
  EXPECT_FALSE(failed.ok());
  EXPECT_EQ(failed.errorText(), "no");
}

TEST(Status, SuccessOrAnError) {
  EXPECT_TRUE(Status::success().ok());
  Status failed = Error("x.json", "not a model");
  EXPECT_FALSE(failed.ok());
  EXPECT_EQ(failed.errorText(), "x.json: not a model");
  EXPECT_EQ(Status::failure("plain").error().message, "plain");
}

}  // namespace
}  // namespace tactile
