// GCC 12 reports false -Wmaybe-uninitialized inside Eigen's AVX-512 kernels at -O3.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include "analysis/feature_table.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "analysis/gmm_synthetic.h"

namespace tactile::analysis {
namespace {

TEST(FeatureTable, ParsesRowsLabelsAndClassOrder) {
  const auto r =
      parseFeatureTable("f0,f1,label\r\n1.5,-2,Wall\r\n\r\n3,4e-3,Corner\n0,0,Wall\n", "a.csv");
  ASSERT_TRUE(r.ok()) << r.errorText();
  EXPECT_EQ(r->dimension(), 2);
  EXPECT_EQ(r->rows(), 3);
  EXPECT_EQ(r->classNames, (std::vector<std::string>{"Wall", "Corner"}));
  EXPECT_EQ(r->labels, (std::vector<int>{0, 1, 0}));
  EXPECT_EQ(r->features(1, 1), 4e-3);
  EXPECT_EQ(r->lines, (std::vector<int>{2, 4, 5}));
  const auto split = splitByClass(r.value());
  ASSERT_EQ(split.size(), 2u);
  EXPECT_EQ(split[0].rows(), 2);
  EXPECT_EQ(split[0](1, 0), 0.0);
}

// The split of a strided array (a numpy array in C order) keeps each class's rows in row order
// and agrees with the split of the same table in column-major order.
TEST(FeatureTable, SplitByClassOfAnyLayoutKeepsRowOrder) {
  FeatureTable table;
  table.classNames = {"a", "b", "c"};
  table.labels = {2, 0, 0, 1, 2, 0, 2};
  table.features.resize(7, 2);
  for (Eigen::Index r = 0; r < 7; ++r)
    table.features.row(r) << static_cast<double>(r), -0.5 * static_cast<double>(r);
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rowMajor =
      table.features;
  const auto split = splitByClass(rowMajor.data(), 7, 2, 2, 1, table.labels.data(), 3);
  ASSERT_EQ(split.size(), 3u);
  EXPECT_TRUE(split[0].col(0) == Eigen::Vector3d(1, 2, 5)) << split[0];
  ASSERT_EQ(split[1].rows(), 1);
  EXPECT_EQ(split[1](0, 0), 3.0);
  EXPECT_EQ(split[1](0, 1), -1.5);
  EXPECT_TRUE(split[2].col(0) == Eigen::Vector3d(0, 4, 6)) << split[2];
  EXPECT_TRUE(split[2].col(1) == Eigen::Vector3d(0, -2, -3)) << split[2];
  const auto fromTable = splitByClass(table);
  ASSERT_EQ(fromTable.size(), 3u);
  for (std::size_t c = 0; c < 3; ++c)
    EXPECT_TRUE(fromTable[c] == split[c]) << c;
  const int bad[] = {0, 3};
  EXPECT_THROW(splitByClass(rowMajor.data(), 2, 2, 2, 1, bad, 3), std::invalid_argument);
}

TEST(FeatureTable, BadNumberNamesFileLineAndColumn) {
  const auto r = parseFeatureTable("f0,f1,label\n1,2,a\n1,x2,b\n", "data/b.csv");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.errorText(), "data/b.csv:3: column 2 (f1): 'x2' is not a finite number");
}

TEST(FeatureTable, NonFiniteNumbersAreRejected) {
  EXPECT_FALSE(parseFeatureTable("f0,label\ninf,a\n", "t.csv").ok());
  EXPECT_FALSE(parseFeatureTable("f0,label\nnan,a\n", "t.csv").ok());
  EXPECT_FALSE(parseFeatureTable("f0,label\n1e999,a\n", "t.csv").ok());
}

TEST(FeatureTable, WrongFieldCountsAreErrors) {
  const auto few = parseFeatureTable("f0,f1,label\n1,a\n", "t.csv");
  ASSERT_FALSE(few.ok());
  EXPECT_NE(few.errorText().find("t.csv:2: expected 3 fields"), std::string::npos)
      << few.errorText();
  const auto many = parseFeatureTable("f0,label\n1,a,b\n", "t.csv");
  ASSERT_FALSE(many.ok());
  EXPECT_NE(many.errorText().find("t.csv:2:"), std::string::npos);
}

TEST(FeatureTable, EmptyLabelIsAnError) {
  const auto r = parseFeatureTable("f0,label\n1,\n", "t.csv");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.errorText(), "t.csv:2: column 2 (label): empty label");
}

TEST(FeatureTable, HeaderMustNameTheColumns) {
  EXPECT_FALSE(parseFeatureTable("a,b,label\n1,2,x\n", "t.csv").ok());
  EXPECT_FALSE(parseFeatureTable("f0,f1\n1,2\n", "t.csv").ok());
  const auto r = parseFeatureTable("f0,f2,label\n1,2,x\n", "t.csv");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errorText().find("t.csv:1: column 2"), std::string::npos) << r.errorText();
}

TEST(FeatureTable, EmptyFileAndHeaderOnlyAreErrors) {
  EXPECT_FALSE(parseFeatureTable("", "t.csv").ok());
  const auto r = parseFeatureTable("f0,label\n", "t.csv");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errorText().find("no rows"), std::string::npos);
}

TEST(FeatureTable, FormatThenParseIsExact) {
  SyntheticTableSpec spec;
  spec.rows = 200;
  spec.dimension = 4;
  const FeatureTable t = makeSyntheticTable(spec);
  const auto r = parseFeatureTable(formatFeatureTable(t), "mem");
  ASSERT_TRUE(r.ok()) << r.errorText();
  EXPECT_TRUE(r->features == t.features);
  EXPECT_EQ(r->labels, t.labels);
  EXPECT_EQ(r->classNames, t.classNames);
}

TEST(FeatureTable, RemapNamesTheUnknownLabelsLine) {
  auto r = parseFeatureTable("f0,label\n1,b\n2,zz\n", "test.csv");
  ASSERT_TRUE(r.ok());
  const Status unknown = remapLabels(r.value(), {"a", "b"}, "test.csv");
  ASSERT_FALSE(unknown.ok());
  EXPECT_EQ(unknown.errorText(), "test.csv:3: label 'zz' does not occur in the training table");
  EXPECT_EQ(unknown.error().line, 3u);
  auto ok = parseFeatureTable("f0,label\n1,b\n2,a\n", "test.csv");
  ASSERT_TRUE(remapLabels(ok.value(), {"a", "b"}, "test.csv").ok());
  EXPECT_EQ(ok->labels, (std::vector<int>{1, 0}));
}

}  // namespace
}  // namespace tactile::analysis
