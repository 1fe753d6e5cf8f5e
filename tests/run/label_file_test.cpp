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
  const LabelFileResult r = parseLabelCsv(text, "l.csv");
  ASSERT_TRUE(r.error.empty()) << r.error;
  ASSERT_EQ(r.records.size(), 2u);
  EXPECT_EQ(r.records[0].group, SensorGroup::Right);
  EXPECT_EQ(r.records[0].lastStep, 4);
  EXPECT_EQ(r.records[0].annotator, "ann");
  EXPECT_EQ(r.records[1].group, SensorGroup::FrontLeftCorner);
  EXPECT_EQ(r.records[1].cls, ContactClass::Corner);
}

TEST(LabelFile, ColumnsFoundByName) {
  const LabelFileResult r =
      parseLabelCsv("class,last_step,first_step,group,run\nWall,3,1,L,x\n", "l.csv");
  ASSERT_TRUE(r.error.empty()) << r.error;
  EXPECT_EQ(r.records[0].firstStep, 1);
  EXPECT_EQ(r.records[0].lastStep, 3);
  EXPECT_EQ(r.records[0].run, "x");
}

TEST(LabelFile, UnknownClassIsErrorWithLine) {
  const LabelFileResult r =
      parseLabelCsv("run,group,first_step,last_step,class\nr,R,0,1,Wall\nr,R,2,3,wall\n", "l.csv");
  EXPECT_FALSE(r.error.empty());
  EXPECT_NE(r.error.find("l.csv:3:"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("class"), std::string::npos);
}

TEST(LabelFile, LastBeforeFirstIsError) {
  const LabelFileResult r =
      parseLabelCsv("run,group,first_step,last_step,class\nr,R,5,4,Wall\n", "l.csv");
  EXPECT_FALSE(r.error.empty());
  EXPECT_NE(r.error.find("l.csv:2:"), std::string::npos) << r.error;
}

TEST(LabelFile, UnknownGroupIsError) {
  const LabelFileResult r =
      parseLabelCsv("run,group,first_step,last_step,class\nr,X,0,1,Wall\n", "l.csv");
  EXPECT_FALSE(r.error.empty());
  EXPECT_NE(r.error.find("group"), std::string::npos);
}

TEST(LabelFile, MissingColumnIsError) {
  const LabelFileResult r = parseLabelCsv("run,group,first_step,class\n", "l.csv");
  EXPECT_FALSE(r.error.empty());
  EXPECT_NE(r.error.find("last_step"), std::string::npos);
}

TEST(LabelFile, WrongFieldCountIsError) {
  const LabelFileResult r =
      parseLabelCsv("run,group,first_step,last_step,class\nr,R,0,1\n", "l.csv");
  EXPECT_FALSE(r.error.empty());
  EXPECT_NE(r.error.find("l.csv:2:"), std::string::npos);
}

TEST(LabelFile, TrailingBlankLinesAreAcceptedButNotBetweenRows) {
  EXPECT_TRUE(parseLabelCsv("run,group,first_step,last_step,class\nr,R,0,1,Wall\n\n", "l.csv")
                  .error.empty());
  const LabelFileResult r = parseLabelCsv(
      "run,group,first_step,last_step,class\nr,R,0,1,Wall\n\nr,R,2,3,Wall\n", "l.csv");
  EXPECT_NE(r.error.find("l.csv:3:"), std::string::npos) << r.error;
}

TEST(LabelFile, CsvAndJsonRoundTrip) {
  std::vector<LabelRecord> records{
      {"run-a", SensorGroup::Left, 0, 9, ContactClass::Wall, "ann"},
      {"run-b", SensorGroup::FrontRightCorner, 3, 3, ContactClass::DeadPath, ""}};
  for (const bool json : {false, true}) {
    const std::string text =
        json ? formatLabelJson(records, "set", "ann") : formatLabelCsv(records);
    const LabelFileResult back =
        json ? parseLabelJson(text, "l.json") : parseLabelCsv(text, "l.csv");
    ASSERT_TRUE(back.error.empty()) << back.error;
    ASSERT_EQ(back.records.size(), records.size());
    for (std::size_t i = 0; i < records.size(); ++i) {
      EXPECT_EQ(back.records[i].run, records[i].run);
      EXPECT_EQ(back.records[i].group, records[i].group);
      EXPECT_EQ(back.records[i].firstStep, records[i].firstStep);
      EXPECT_EQ(back.records[i].lastStep, records[i].lastStep);
      EXPECT_EQ(back.records[i].cls, records[i].cls);
      EXPECT_EQ(back.records[i].annotator, records[i].annotator);
    }
  }
}

}  // namespace
}  // namespace tactile
