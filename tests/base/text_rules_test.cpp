// The one name rule and the text helpers every reader and writer uses (base/text_rules.h).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "base/text_rules.h"

namespace tactile {
namespace {

TEST(NameRule, AcceptsOrdinaryAndMultiByteNames) {
  for (const std::string& name : std::vector<std::string>{
           "run_0000", "a", "Müller's set", "ラン 1", "-starts-with-dash", " spaced ", "x;y|z/w",
           std::string(kMaxNameBytes, 'n'), std::string("\xF0\x9F\x98\x80")}) {
    EXPECT_EQ(nameProblem(name), std::nullopt) << name;
    EXPECT_TRUE(checkName(name, "run").ok()) << name;
  }
}

TEST(NameRule, RefusesEachBrokenRuleAndSaysWhich) {
  struct Case {
    std::string name;
    std::string fragment;
  };
  const Case cases[] = {
      {"", "empty"},
      {"a,b", "comma at byte 2"},
      {"a\nb", "control character"},
      {"a\rb", "control character"},
      {"tab\there", "control character"},
      {std::string("nul\0x", 5), "control character"},
      {"del\x7F", "control character"},
      {"c1\xC2\x85", "U+0085"},  // NEXT LINE, a C1 control
      {"caf\xE9", "not valid UTF-8 (byte 0xE9 at byte 4)"},
      {"\xC0\xAF", "not valid UTF-8"},          // overlong '/'
      {"\xED\xA0\x80", "not valid UTF-8"},      // a surrogate
      {"\xF4\x90\x80\x80", "not valid UTF-8"},  // above U+10FFFF
      {"trunc\xE3\x81", "not valid UTF-8"},
      {std::string(kMaxNameBytes + 1, 'n'), "201 bytes long (at most 200)"},
  };
  for (const Case& c : cases) {
    const auto problem = nameProblem(c.name);
    ASSERT_TRUE(problem.has_value()) << shownText(c.name);
    EXPECT_NE(problem->find(c.fragment), std::string::npos) << *problem;
    const Status status = checkName(c.name, "label set");
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.errorText().find("label set"), std::string::npos) << status.errorText();
    // The message itself is always printable UTF-8 without control characters.
    EXPECT_TRUE(isValidUtf8(status.errorText())) << status.errorText();
    for (char ch : status.errorText())
      EXPECT_FALSE(static_cast<unsigned char>(ch) < 0x20) << status.errorText();
  }
}

TEST(NameRule, LengthCountsBytesNotCharacters) {
  std::string name;
  for (int i = 0; i < 100; ++i)
    name += "\xC3\xA9";  // 100 characters, 200 bytes
  EXPECT_EQ(nameProblem(name), std::nullopt);
  name += "e";
  EXPECT_TRUE(nameProblem(name).has_value());
}

TEST(NameFromFileStem, ReplacesCommasAndControlsButNotInvalidBytes) {
  EXPECT_EQ(nameFromFileStem("run,one"), "run_one");
  EXPECT_EQ(nameFromFileStem("a\nb\tc"), "a_b_c");
  EXPECT_EQ(nameFromFileStem("x\xC2\x85y"), "x__y");
  EXPECT_EQ(nameFromFileStem("caf\xC3\xA9"), "caf\xC3\xA9");
  // Invalid UTF-8 stays, so the rule refuses it instead of storing a guess.
  EXPECT_EQ(nameFromFileStem("caf\xE9"), "caf\xE9");
  EXPECT_TRUE(nameProblem(nameFromFileStem("caf\xE9")).has_value());
  EXPECT_EQ(nameProblem(nameFromFileStem("run,one\r")), std::nullopt);
}

TEST(ShownText, EscapesWhatCannotBePrinted) {
  EXPECT_EQ(shownText("plain"), "plain");
  EXPECT_EQ(shownText("0\f"), "0\\x0C");
  EXPECT_EQ(shownText("caf\xE9"), "caf\\xE9");
  EXPECT_EQ(shownText("caf\xC3\xA9"), "caf\xC3\xA9");
  EXPECT_EQ(shownText("abcdef", 3), "abc...");
}

// The one way readers quote input: at most kMaxQuotedBytes of it, so a 10 MB line gives a short
// message; a cut never splits a UTF-8 character.
TEST(QuotedInput, CutsLongInput) {
  EXPECT_EQ(quotedInput("n3"), "'n3'");
  EXPECT_EQ(quotedInput("0\f"), "'0\\x0C'");
  const std::string big(10'000'000, 'a');
  const std::string q = quotedInput(big);
  EXPECT_EQ(q, "'" + std::string(kMaxQuotedBytes, 'a') + "...'");
  std::string accents;
  for (int i = 0; i < 150; ++i)
    accents += "\xC3\xA9";
  const std::string cut = quotedInput(accents);
  EXPECT_TRUE(isValidUtf8(cut)) << cut;
  EXPECT_EQ(cut.find("\\x"), std::string::npos) << cut;
  EXPECT_LE(cut.size(), kMaxQuotedBytes + 5);
}

TEST(ValidUtf8, ReplacesEachBadByte) {
  EXPECT_EQ(validUtf8("caf\xE9!"), "caf\xEF\xBF\xBD!");
  EXPECT_EQ(validUtf8("ok \xC3\xA9"), "ok \xC3\xA9");
  EXPECT_EQ(invalidUtf8At("abcdefghij\xFFz"), 10u);
  EXPECT_TRUE(isValidUtf8(validUtf8("\xFF\xFE\xC3")));
}

}  // namespace
}  // namespace tactile
