// The one label-file reader (sim/label_file.h), used by storage and analysis alike.
#include <gtest/gtest.h>

#include "run/label_file.h"

namespace tactile {
namespace {

TEST(LabelFile, ParsesSegmentsWithBomCrlfAndAnnotator) {
  const std::string text =
      "\xEF\xBB\xBFrun,group,first_step,last_step,class,annotator\r\n"
      "r1,R,0,4,Wall,ann\r\n"
      "r1,front-left corner,5,5,Corner,\r\n";
  const auto r = parseLabelCsv(text, "l.csv");
  ASSERT_TRUE(r.ok()) << r.errorText();
  ASSERT_EQ(r->records.size(), 2u);
  EXPECT_EQ(r->records[0].group, SensorGroup::Right);
  EXPECT_EQ(r->records[0].lastStep, 4);
  EXPECT_EQ(r->records[0].annotator, "ann");
  EXPECT_EQ(r->records[1].group, SensorGroup::FrontLeftCorner);
  EXPECT_EQ(r->records[1].cls, ContactClass::Corner);
}

TEST(LabelFile, ColumnsFoundByName) {
  const auto r = parseLabelCsv("class,last_step,first_step,group,run\nWall,3,1,L,x\n", "l.csv");
  ASSERT_TRUE(r.ok()) << r.errorText();
  EXPECT_EQ(r->records[0].firstStep, 1);
  EXPECT_EQ(r->records[0].lastStep, 3);
  EXPECT_EQ(r->records[0].run, "x");
}

TEST(LabelFile, UnknownClassIsErrorWithLine) {
  const auto r =
      parseLabelCsv("run,group,first_step,last_step,class\nr,R,0,1,Wall\nr,R,2,3,wall\n", "l.csv");
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.errorText().find("l.csv:3:"), std::string::npos) << r.errorText();
  EXPECT_NE(r.errorText().find("class"), std::string::npos);
}

TEST(LabelFile, LastBeforeFirstIsError) {
  const auto r = parseLabelCsv("run,group,first_step,last_step,class\nr,R,5,4,Wall\n", "l.csv");
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.errorText().find("l.csv:2:"), std::string::npos) << r.errorText();
}

TEST(LabelFile, UnknownGroupIsError) {
  const auto r = parseLabelCsv("run,group,first_step,last_step,class\nr,X,0,1,Wall\n", "l.csv");
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.errorText().find("group"), std::string::npos);
}

TEST(LabelFile, MissingColumnIsError) {
  const auto r = parseLabelCsv("run,group,first_step,class\n", "l.csv");
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.errorText().find("last_step"), std::string::npos);
}

TEST(LabelFile, WrongFieldCountIsError) {
  const auto r = parseLabelCsv("run,group,first_step,last_step,class\nr,R,0,1\n", "l.csv");
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.errorText().find("l.csv:2:"), std::string::npos);
}

TEST(LabelFile, TrailingBlankLinesAreAcceptedButNotBetweenRows) {
  EXPECT_TRUE(
      parseLabelCsv("run,group,first_step,last_step,class\nr,R,0,1,Wall\n\n", "l.csv").ok());
  const auto r = parseLabelCsv(
      "run,group,first_step,last_step,class\nr,R,0,1,Wall\n\nr,R,2,3,Wall\n", "l.csv");
  EXPECT_NE(r.errorText().find("l.csv:3:"), std::string::npos) << r.errorText();
}

TEST(LabelFile, CsvAndJsonRoundTrip) {
  std::vector<LabelRecord> records{
      {"run-a", SensorGroup::Left, 0, 9, ContactClass::Wall, "ann"},
      {"run-b", SensorGroup::FrontRightCorner, 3, 3, ContactClass::DeadPath, ""}};
  for (const bool json : {false, true}) {
    const std::string text =
        json ? formatLabelJson(records, "set", "ann") : formatLabelCsv(records);
    const auto back = json ? parseLabelJson(text, "l.json") : parseLabelCsv(text, "l.csv");
    ASSERT_TRUE(back.ok()) << back.errorText();
    ASSERT_EQ(back->records.size(), records.size());
    for (std::size_t i = 0; i < records.size(); ++i) {
      EXPECT_EQ(back->records[i].run, records[i].run);
      EXPECT_EQ(back->records[i].group, records[i].group);
      EXPECT_EQ(back->records[i].firstStep, records[i].firstStep);
      EXPECT_EQ(back->records[i].lastStep, records[i].lastStep);
      EXPECT_EQ(back->records[i].cls, records[i].cls);
      EXPECT_EQ(back->records[i].annotator, records[i].annotator);
    }
  }
}

TEST(LabelFile, ProvenanceRoundTripsInCsvAndJson) {
  const std::vector<LabelRecord> records{
      {"room1 run_0000", SensorGroup::Left, 0, 9, ContactClass::Wall, ""}};
  const std::vector<LabelRunProvenance> runs{{"room1 run_0000", 1234, "0123456789abcdef", 0},
                                             {"other", 0, "fedcba9876543210", 0}};
  const std::string csv = formatLabelCsv(records, runs);
  EXPECT_EQ(csv.rfind("# run room1 run_0000 steps 1234 checksum 0123456789abcdef\n"
                      "# run other steps 0 checksum fedcba9876543210\n"
                      "run,group,",
                      0),
            0u)
      << csv;
  for (const bool json : {false, true}) {
    SCOPED_TRACE(json ? "json" : "csv");
    const std::string text = json ? formatLabelJson(records, "set", "", runs) : csv;
    const auto back = json ? parseLabelJson(text, "l.json") : parseLabelCsv(text, "l.csv");
    ASSERT_TRUE(back.ok()) << back.errorText();
    EXPECT_EQ(back->runs, runs);
    ASSERT_EQ(back->records.size(), 1u);
    EXPECT_EQ(back->records[0].run, "room1 run_0000");
    ASSERT_NE(findProvenance(back.value(), "other"), nullptr);
    EXPECT_EQ(findProvenance(back.value(), "other")->steps, 0);
    EXPECT_EQ(findProvenance(back.value(), "ghost"), nullptr);
  }
  EXPECT_EQ(parseLabelCsv(csv, "l.csv")->runs[1].line, 2u);
}

TEST(LabelFile, FilesWithoutProvenanceAndOtherCommentsAreRead) {
  const auto plain = parseLabelCsv("run,group,first_step,last_step,class\nr,R,0,1,Wall\n", "l.csv");
  ASSERT_TRUE(plain.ok()) << plain.errorText();
  EXPECT_TRUE(plain->runs.empty());
  const auto commented = parseLabelCsv(
      "# made by hand\n#run-less note\nrun,group,first_step,last_step,class\nr,R,0,1,Wall\n",
      "l.csv");
  ASSERT_TRUE(commented.ok()) << commented.errorText();
  EXPECT_TRUE(commented->runs.empty());
  EXPECT_EQ(commented->records.size(), 1u);
  EXPECT_EQ(commented->records[0].line, 4u);
}

TEST(LabelFile, MalformedProvenanceIsAnErrorWithItsLine) {
  const std::string header = "run,group,first_step,last_step,class\nr,R,0,1,Wall\n";
  for (const char* bad :
       {"# run r steps 10 checksum 0123\n", "# run r steps ten checksum 0123456789abcdef\n",
        "# run r steps -1 checksum 0123456789abcdef\n", "# run r steps 10 sum 0123456789abcdef\n",
        "# run steps 10 checksum 0123456789abcdef\n",
        "# run r steps 10 checksum 0123456789ABCDEF\n"}) {
    SCOPED_TRACE(bad);
    const auto r = parseLabelCsv("# ok\n" + std::string(bad) + header, "l.csv");
    EXPECT_EQ(r.errorText().rfind("l.csv:2: ", 0), 0u) << r.errorText();
  }
  const auto twice = parseLabelCsv(
      "# run r steps 1 checksum 0123456789abcdef\n"
      "# run r steps 1 checksum 0123456789abcdef\n" +
          header,
      "l.csv");
  EXPECT_EQ(twice.errorText().rfind("l.csv:2: second provenance entry for run 'r'", 0), 0u)
      << twice.errorText();
  EXPECT_FALSE(parseLabelCsv("# run r steps 1 checksum 0123456789abcdef\n", "l.csv").ok());
}

TEST(LabelFile, MalformedJsonProvenanceIsAnError) {
  const auto r = parseLabelJson(
      R"({"runs":[{"name":"r","steps":1,"checksum":"0123456789abcdef"},{"name":"s","steps":"1","checksum":"0123456789abcdef"}],"segments":[]})",
      "l.json");
  EXPECT_EQ(r.errorText(),
            "l.json:1: runs entry 2: \"steps\" holds a string where an integer is needed");
  EXPECT_EQ(r.error().file, "l.json");
  const auto missing =
      parseLabelJson(R"({"runs":[{"name":"r","steps":1}],"segments":[]})", "l.json");
  EXPECT_EQ(missing.errorText(),
            "l.json:1: runs entry 1: expected {\"name\": text, \"steps\": integer, "
            "\"checksum\": text}");
}

// One rule for CSV and JSON label files: a repeated key (CSV: column), a key the format does not
// have (CSV: an unknown column) and a step written -0 are refused, each at the file and line.
TEST(LabelFileHostile, JsonRefusesWhatCsvRefuses) {
  const std::string head = "{\"format\": \"tactile-labels\", \"version\": 1,\n \"segments\": [\n";
  const std::string good =
      R"(  {"run": "r", "group": "F", "first_step": 0, "last_step": 3, "class": "Wall"})";
  ASSERT_TRUE(parseLabelJson(head + good + "\n]}\n", "l.json").ok());

  auto r = parseLabelJson(head + good + ",\n" +
                              R"(  {"run": "r", "group": "F", "first_step": 4, "last_step": 5,)" +
                              "\n   \"class\": \"Wall\", \"class\": \"Corner\"}\n]}\n",
                          "l.json");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().line, 5u) << r.errorText();
  EXPECT_NE(r.errorText().find("duplicate key 'class' (first on line 5)"), std::string::npos)
      << r.errorText();

  r = parseLabelJson(head + good + ",\n" +
                         R"(  {"run": "r", "group": "F", "first_step": 4, "last_step": 5,)" +
                         "\n   \"class\": \"Wall\", \"colour\": \"red\"}\n]}\n",
                     "l.json");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().line, 5u) << r.errorText();
  EXPECT_NE(r.errorText().find("segment 2: unknown key 'colour'"), std::string::npos)
      << r.errorText();

  r = parseLabelJson(head + good + ",\n" +
                         R"(  {"run": "r", "group": "F", "first_step": -0, "last_step": 5,)" +
                         "\n   \"class\": \"Wall\"}\n]}\n",
                     "l.json");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().line, 4u) << r.errorText();
  EXPECT_NE(r.errorText().find("-0"), std::string::npos) << r.errorText();

  r = parseLabelJson("{\"segments\": [],\n \"extra\": 1}", "l.json");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().line, 2u) << r.errorText();
  EXPECT_NE(r.errorText().find("unknown key 'extra'"), std::string::npos) << r.errorText();

  r = parseLabelJson("{\"segments\": [],\n \"segments\": []}", "l.json");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().line, 2u) << r.errorText();

  // The CSV reader: the same three.
  EXPECT_FALSE(parseLabelCsv("run,group,first_step,last_step,class,class\n", "l.csv").ok());
  EXPECT_FALSE(parseLabelCsv("run,group,first_step,last_step,class,colour\n", "l.csv").ok());
  EXPECT_FALSE(
      parseLabelCsv("run,group,first_step,last_step,class\nr,F,-0,3,Wall\n", "l.csv").ok());
}

// A field of the wrong type says what it holds and what is needed.
TEST(LabelFileHostile, JsonFieldOfTheWrongTypeSaysSo) {
  const auto r = parseLabelJson(
      "[\n{\"run\": \"r\", \"group\": \"F\", \"first_step\": \"3\", \"last_step\": 5, "
      "\"class\": \"Wall\"}]",
      "l.json");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.errorText(),
            "l.json:2: segment 1: \"first_step\" holds a string where an integer is needed");
}

// Regression: a JSON first_step of 2^64-1 was read as -1 and reported as "'-1' is not a step".
TEST(LabelFileHostile, HugeJsonStepIsShownAsWritten) {
  const std::string text =
      R"({"segments":[{"run":"r","group":"F","first_step":18446744073709551615,)"
      R"("last_step":3,"class":"Wall"}]})";
  const auto r = parseLabelJson(text, "l.json");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().file, "l.json");
  EXPECT_NE(r.errorText().find("18446744073709551615"), std::string::npos) << r.errorText();
  EXPECT_EQ(r.errorText().find("-1"), std::string::npos) << r.errorText();
}

// Regression: a Latin-1 annotator entered the database and later broke every --json writer.
TEST(LabelFileHostile, AnnotatorsAndRunNamesFollowTheNameRule) {
  auto csv = parseLabelCsv("run,group,first_step,last_step,class,annotator\nr,F,0,1,Wall,Jos\xE9\n",
                           "l.csv");
  ASSERT_FALSE(csv.ok());
  EXPECT_EQ(csv.error().line, 2u);
  EXPECT_NE(csv.errorText().find("annotator"), std::string::npos) << csv.errorText();
  EXPECT_NE(csv.errorText().find("UTF-8"), std::string::npos) << csv.errorText();
  csv = parseLabelCsv("run,group,first_step,last_step,class\nr\x01,F,0,1,Wall\n", "l.csv");
  ASSERT_FALSE(csv.ok());
  EXPECT_EQ(csv.error().line, 2u);
  EXPECT_NE(csv.errorText().find("control character"), std::string::npos) << csv.errorText();
  // JSON strings may hold commas and line breaks; names may not.
  auto json = parseLabelJson(
      R"([{"run":"r","group":"F","first_step":0,"last_step":1,"class":"Wall","annotator":"a\nb"}])",
      "l.json");
  ASSERT_FALSE(json.ok());
  EXPECT_NE(json.errorText().find("segment 1"), std::string::npos) << json.errorText();
  json = parseLabelJson(
      R"([{"run":"a,b","group":"F","first_step":0,"last_step":1,"class":"Wall"}])", "l.json");
  ASSERT_FALSE(json.ok());
  EXPECT_NE(json.errorText().find("comma"), std::string::npos) << json.errorText();
  // A valid multi-byte annotator is kept.
  csv = parseLabelCsv("run,group,first_step,last_step,class,annotator\nr,F,0,1,Wall,Jos\xC3\xA9\n",
                      "l.csv");
  ASSERT_TRUE(csv.ok()) << csv.errorText();
  EXPECT_EQ(csv->records[0].annotator, "Jos\xC3\xA9");
}

TEST(LabelFileHostile, StepsAreIntegerLiteralsWithoutSignOrLeadingZero) {
  for (const char* bad : {"-0", "00", "01", "+1"}) {
    SCOPED_TRACE(bad);
    const auto r = parseLabelCsv(
        std::string("run,group,first_step,last_step,class\nr,F,") + bad + ",3,Wall\n", "l.csv");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().line, 2u);
  }
}

// JSON syntax errors name the line and column; number overflow too.
TEST(LabelFileHostile, JsonErrorsNameLineAndColumn) {
  auto r = parseLabelJson("{\n \"segments\": [\n  {\"run\": 1e400}]}", "l.json");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().file, "l.json");
  EXPECT_EQ(r.error().line, 3u);
  EXPECT_NE(r.errorText().find("overflow"), std::string::npos) << r.errorText();
  r = parseLabelJson("[\n\n  {\"run\": \"x\",}]", "l.json");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().line, 3u) << r.errorText();
  EXPECT_GT(r.error().column, 0u);
  r = parseLabelJson(std::string(100000, '['), "deep.json");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errorText().find("nested deeper"), std::string::npos) << r.errorText();
}

}  // namespace
}  // namespace tactile
