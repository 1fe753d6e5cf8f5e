#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>

#include "base/file_text.h"
#include "run/run_csv.h"
#include "run/synthetic_run.h"
#include "tests/run_compare.h"

namespace tactile {
namespace {

RunData makeRun(std::size_t steps, bool withTruth, unsigned seed = 1) {
  return makeSyntheticRun(steps, withTruth, seed);
}

using test_support::bitEqual;
using test_support::expectSameRun;

// The text of a small valid run (3 steps, with truth) to be broken by each test.
std::string validText() {
  return formatRunCsv(makeRun(3, true));
}

std::size_t metadataLineCount() {
  return 6;
}

// Replaces physical line `lineNo` (1-based) of `text`.
std::string replaceLine(const std::string& text, std::size_t lineNo, const std::string& line) {
  std::size_t begin = 0;
  for (std::size_t i = 1; i < lineNo; ++i)
    begin = text.find('\n', begin) + 1;
  const std::size_t end = text.find('\n', begin);
  return text.substr(0, begin) + line + text.substr(end);
}

std::string lineAt(const std::string& text, std::size_t lineNo) {
  std::size_t begin = 0;
  for (std::size_t i = 1; i < lineNo; ++i)
    begin = text.find('\n', begin) + 1;
  return text.substr(begin, text.find('\n', begin) - begin);
}

// Replaces field `position` (1-based) of line `lineNo`.
std::string replaceField(const std::string& text, std::size_t lineNo, std::size_t position,
                         const std::string& value) {
  std::string line = lineAt(text, lineNo);
  std::size_t begin = 0;
  for (std::size_t i = 1; i < position; ++i)
    begin = line.find(',', begin) + 1;
  std::size_t end = line.find(',', begin);
  if (end == std::string::npos) end = line.size();
  line = line.substr(0, begin) + value + line.substr(end);
  return replaceLine(text, lineNo, line);
}

// Chunk sizes that cut small files at every line, at some lines, and not at all.
constexpr std::size_t kChunkSizes[] = {1, 37, 300, std::size_t{1} << 20};

// Parsing in chunks must give exactly the sequential result: the same run or the same error.
void expectChunkedSame(const std::string& text, const RunCsvResult& sequential) {
  for (std::size_t chunkBytes : kChunkSizes) {
    SCOPED_TRACE("chunk bytes " + std::to_string(chunkBytes));
    RunCsvResult chunked = parseRunCsvParallel(text, "bad.csv", 2, chunkBytes);
    ASSERT_EQ(chunked.ok(), sequential.ok());
    if (sequential.ok()) {
      expectSameRun(chunked.value(), sequential.value());
      EXPECT_EQ(chunked.value().metadata, sequential.value().metadata);
      EXPECT_EQ(chunked.value().extraColumns, sequential.value().extraColumns);
      EXPECT_EQ(chunked.value().extraValues, sequential.value().extraValues);
    } else {
      EXPECT_EQ(chunked.errorText(), sequential.errorText());
      EXPECT_EQ(chunked.error().line, sequential.error().line);
      EXPECT_EQ(chunked.error().column, sequential.error().column);
    }
  }
}

// `column` "*" skips the column check.
Error expectError(const std::string& text, std::size_t line, const std::string& column,
                  const std::string& fragment) {
  RunCsvResult result = parseRunCsv(text, "bad.csv");
  expectChunkedSame(text, result);
  EXPECT_FALSE(result.ok()) << "accepted a bad file";
  if (result.ok()) return {};
  const Error& e = result.error();
  EXPECT_EQ(e.file, "bad.csv");
  EXPECT_EQ(e.line, line) << e.text();
  if (column == "") {
    EXPECT_FALSE(e.message.starts_with("column '")) << e.text();
  } else if (column != "*") {
    EXPECT_TRUE(e.message.starts_with("column '" + column + "' (position ")) << e.text();
  }
  EXPECT_NE(e.message.find(fragment), std::string::npos) << e.text();
  return e;
}

const std::size_t kHeader = metadataLineCount() + 1;  // physical line of the header
const std::size_t kRow0 = kHeader + 1;

TEST(RunCsv, RoundTripIsBitExact) {
  RunData run = makeRun(200, true, 7);
  run.x[3] = -0.0;
  run.y[4] = std::numeric_limits<double>::denorm_min();
  run.theta[5] = 1e300;
  run.v[6] = 0.1 + 0.2;
  const std::string text = formatRunCsv(run);
  RunCsvResult back = parseRunCsv(text, "rt.csv");
  ASSERT_TRUE(back.ok()) << back.errorText();
  expectSameRun(run, back.value());
  EXPECT_TRUE(std::signbit(back.value().x[3]));
  EXPECT_EQ(formatRunCsv(back.value()), text);
}

TEST(RunCsv, RoundTripWithoutTruthAndWithExtraColumns) {
  RunData run = makeRun(5, false);
  run.extraColumns = {"x_note", "x_operator"};
  for (std::size_t i = 0; i < 5; ++i) {
    run.extraValues.push_back("n" + std::to_string(i));
    run.extraValues.push_back(i == 2 ? "" : "ann");
  }
  RunCsvResult back = parseRunCsv(formatRunCsv(run), "x.csv");
  ASSERT_TRUE(back.ok()) << back.errorText();
  EXPECT_FALSE(back.value().hasTruth());
  expectSameRun(run, back.value());
}

TEST(RunCsv, HundredThousandStepFileRoundTrips) {
  const RunData run = makeRun(100000, true, 3);
  const auto path = std::filesystem::temp_directory_path() / "tactile_run_100k.csv";
  ASSERT_TRUE(writeRunCsv(run, path).ok());
  RunCsvResult back = readRunCsv(path);
  std::filesystem::remove(path);
  ASSERT_TRUE(back.ok()) << back.errorText();
  ASSERT_EQ(back.value().stepCount(), 100000u);
  expectSameRun(run, back.value());
}

TEST(RunCsv, ColumnsAreFoundByNameInAnyOrder) {
  // A hand-written file with reordered columns: omega first, sensors interleaved backwards.
  std::string header = "omega";
  std::string row0 = "0.25";
  for (int s = kSensorCount - 1; s >= 0; --s) {
    header += ",s" + std::to_string(s) + ",n" + std::to_string(s);
    row0 += s == 5 ? ",-1.5,2.5" : ",0,0";
  }
  header += ",blocked,theta,y,x,step,v,x_tag";
  row0 += ",1,0.5,2,1,0,3,hello";
  RunCsvResult r = parseRunCsv(header + "\n" + row0 + "\n", "order.csv");
  ASSERT_TRUE(r.ok()) << r.errorText();
  const RunData& run = r.value();
  EXPECT_EQ(run.stepCount(), 1u);
  EXPECT_EQ(run.omega[0], 0.25);
  EXPECT_EQ(run.x[0], 1.0);
  EXPECT_EQ(run.y[0], 2.0);
  EXPECT_EQ(run.v[0], 3.0);
  EXPECT_EQ(run.blocked[0], 1);
  EXPECT_EQ(run.normal(0, 5), 2.5);
  EXPECT_EQ(run.shear(0, 5), -1.5);
  EXPECT_EQ(run.extraValues[0], "hello");
}

TEST(RunCsv, AcceptsBomCrlfAndMissingFinalNewline) {
  std::string text = validText();
  std::string crlf;
  for (char c : text) {
    if (c == '\n') crlf += '\r';
    crlf += c;
  }
  crlf.pop_back();  // no final newline
  crlf.pop_back();
  RunCsvResult r = parseRunCsv("\xEF\xBB\xBF" + crlf, "bom.csv");
  ASSERT_TRUE(r.ok()) << r.errorText();
  RunCsvResult plain = parseRunCsv(text, "plain.csv");
  ASSERT_TRUE(plain.ok());
  expectSameRun(plain.value(), r.value());
}

TEST(RunCsv, MetadataIsOptionalAndUnknownKeysAreKept) {
  std::string text = validText();
  const std::size_t headerStart = text.find("step,");
  RunCsvResult bare = parseRunCsv(text.substr(headerStart), "bare.csv");
  ASSERT_TRUE(bare.ok()) << bare.errorText();
  EXPECT_TRUE(bare.value().metadata.empty());
  RunCsvResult extra = parseRunCsv("# robot: obrero-2\n" + text, "m.csv");
  ASSERT_TRUE(extra.ok()) << extra.errorText();
  ASSERT_NE(extra.value().meta("robot"), nullptr);
  EXPECT_EQ(*extra.value().meta("robot"), "obrero-2");
  EXPECT_EQ(extra.value().dtSeconds(), 0.1);
  EXPECT_EQ(extra.value().outcome(), RunOutcome::Success);
  ASSERT_TRUE(extra.value().start());
  EXPECT_EQ(extra.value().start()->theta, 0.5);
}

TEST(Errors, EmptyFile) {
  expectError("", 0, "", "empty file");
  expectError("\xEF\xBB\xBF", 0, "", "empty file");
}

TEST(Errors, HeaderOnly) {
  std::string text = validText();
  text = text.substr(0, text.find('\n', text.find("step,")) + 1);
  expectError(text, kHeader, "", "no steps");
}

TEST(Errors, MissingColumn) {
  std::string text = validText();
  std::string header = lineAt(text, kHeader);
  header.replace(header.find(",n12,"), 5, ",x_n12,");
  expectError(replaceLine(text, kHeader, header), kHeader, "", "missing column 'n12'");
}

TEST(Errors, DuplicateColumn) {
  std::string text = validText();
  std::string header = lineAt(text, kHeader);
  header.replace(header.find(",s3,"), 4, ",s2,");
  const Error e = expectError(replaceLine(text, kHeader, header), kHeader, "s2", "duplicate");
  // step..blocked are 7 columns, then n0 s0 n1 s1 n2 s2 n3 s3: s3 is the 15th, s2 the 13th.
  EXPECT_EQ(e.column, 15u);
  EXPECT_NE(e.message.find("first at position 13"), std::string::npos);
}

// The duplicate check covers the first and the last column too: a header that starts with `x`
// and repeats it at the end, and the same with an `x_` column.
TEST(Errors, DuplicateOfTheFirstColumnAtTheEnd) {
  const std::string text = validText();
  std::string header = lineAt(text, kHeader);  // step,x,y,...
  header.replace(0, header.find(",y,"), "x,step");
  const std::size_t columns =
      static_cast<std::size_t>(std::count(header.begin(), header.end(), ',')) + 1;
  const Error e =
      expectError(replaceLine(text, kHeader, header + ",x"), kHeader, "x", "duplicate column 'x'");
  EXPECT_EQ(e.column, columns + 1);
  EXPECT_NE(e.message.find("first at position 1)"), std::string::npos) << e.text();

  const Error extra =
      expectError(replaceLine(text, kHeader, "x_a," + lineAt(text, kHeader) + ",x_a"), kHeader,
                  "x_a", "duplicate column 'x_a'");
  EXPECT_EQ(extra.column, columns + 2);
  EXPECT_NE(extra.message.find("first at position 1)"), std::string::npos) << extra.text();
}

// Many `x_` columns are checked for repeats with one look-up each; past kMaxRunColumns the header
// is refused at the column that goes past it. (200,000 columns took over a minute when every
// column was compared with every other; now the check stops at the limit.)
TEST(Errors, TooManyColumns) {
  const std::string text = validText();
  std::string header = lineAt(text, kHeader);
  const std::size_t base =
      static_cast<std::size_t>(std::count(header.begin(), header.end(), ',')) + 1;
  std::string many = header;
  for (std::size_t i = 0; i < 200'000; ++i)
    many += ",x_" + std::to_string(i);
  const RunCsvResult r = parseRunCsv(replaceLine(text, kHeader, many), "bad.csv");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().line, kHeader);
  EXPECT_NE(r.error().message.find("too many columns"), std::string::npos) << r.errorText();
  EXPECT_NE(r.error().message.find("at most " + std::to_string(kMaxRunColumns)), std::string::npos);
  EXPECT_NE(r.error().message.find("position " + std::to_string(kMaxRunColumns + 1)),
            std::string::npos)
      << r.errorText();

  // Up to the limit is fine, and a repeat among them is found and named.
  std::string full = header;
  for (std::size_t i = base; i < kMaxRunColumns; ++i)
    full += ",x_" + std::to_string(i);
  const std::string repeated = full.substr(0, full.rfind(',')) + ",x_" + std::to_string(base);
  const Error e =
      expectError(replaceLine(text, kHeader, repeated), kHeader, "*", "duplicate column");
  EXPECT_EQ(e.column, kMaxRunColumns);
  EXPECT_NE(e.message.find("first at position " + std::to_string(base + 1)), std::string::npos)
      << e.text();
}

TEST(Errors, TooManyMetadataLines) {
  std::string head;
  for (std::size_t i = 0; i < 200'000; ++i)
    head += "# key" + std::to_string(i) + ": value\n";
  const RunCsvResult r = parseRunCsv(head + validText(), "bad.csv");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().line, kMaxRunMetadataLines + 1);
  EXPECT_NE(r.error().message.find("too many metadata lines"), std::string::npos) << r.errorText();

  // Below the limit a repeat is found among thousands and names the first line.
  std::string some;
  for (std::size_t i = 0; i < 5'000; ++i)
    some += "# key" + std::to_string(i) + ": value\n";
  const Error e = expectError(some + "# key0: again\n" + validText(), 5'001, "",
                              "repeated metadata key 'key0'");
  EXPECT_NE(e.message.find("first given on line 1)"), std::string::npos) << e.text();
}

TEST(Errors, UnknownColumn) {
  std::string text = validText();
  text = replaceField(text, kHeader, 3, "why");
  expectError(text, kHeader, "why", "unknown column 'why'");
  // Look-alikes of real columns are unknown too.
  expectError(replaceField(validText(), kHeader, 9, "n00"), kHeader, "n00", "unknown column");
  expectError(replaceField(validText(), kHeader, 9, "n44"), kHeader, "n44", "unknown column");
}

TEST(Errors, PartialTruthColumns) {
  std::string text = validText();
  std::string header = lineAt(text, kHeader);
  header.replace(header.find(",truth_RRC"), 10, ",x_RRC");
  expectError(replaceLine(text, kHeader, header), kHeader, "", "missing column 'truth_RRC'");
}

TEST(Errors, WrongFieldCount) {
  std::string text = validText();
  std::string row = lineAt(text, kRow0 + 1);
  const std::size_t fields = std::count(row.begin(), row.end(), ',') + 1;
  // One field too many.
  Error e = expectError(
      replaceLine(text, kRow0 + 1, row + ",7"), kRow0 + 1, "",
      "expected " + std::to_string(fields) + " fields, found " + std::to_string(fields + 1));
  EXPECT_EQ(e.column, fields + 1);
  // One field too few: the first missing column is named.
  row = row.substr(0, row.rfind(','));
  e = expectError(replaceLine(text, kRow0 + 1, row), kRow0 + 1, "truth_FRC", "found");
  EXPECT_EQ(e.column, fields);
}

TEST(Errors, NonNumber) {
  expectError(replaceField(validText(), kRow0, 2, "abc"), kRow0, "x", "expected a number");
  expectError(replaceField(validText(), kRow0, 2, ""), kRow0, "x", "empty field");
  expectError(replaceField(validText(), kRow0, 3, "+1"), kRow0, "y", "expected a number");
  expectError(replaceField(validText(), kRow0, 3, "0x1p3"), kRow0, "y", "expected a number");
  expectError(replaceField(validText(), kRow0, 4, " 1"), kRow0, "theta", "expected a number");
  expectError(replaceField(validText(), kRow0, 4, "\"1\""), kRow0, "theta", "expected a number");
  expectError(replaceField(validText(), kRow0, 1, "0.0"), kRow0, "step", "integer");
  expectError(replaceField(validText(), kRow0, 7, "yes"), kRow0, "blocked", "0 or 1");
}

TEST(Errors, NanAndInfinity) {
  expectError(replaceField(validText(), kRow0, 5, "nan"), kRow0, "v", "finite");
  expectError(replaceField(validText(), kRow0, 6, "inf"), kRow0, "omega", "finite");
  expectError(replaceField(validText(), kRow0, 6, "-infinity"), kRow0, "omega", "finite");
  expectError(replaceField(validText(), kRow0, 2, "1e999"), kRow0, "x", "finite");
}

TEST(Errors, ValueOutOfRange) {
  expectError(replaceField(validText(), kRow0 + 2, 8, "5.0001"), kRow0 + 2, "n0", "[0, 5]");
  expectError(replaceField(validText(), kRow0, 8, "-0.5"), kRow0, "n0", "[0, 5]");
  expectError(replaceField(validText(), kRow0, 9, "-5.5"), kRow0, "s0", "[-5, 5]");
  expectError(replaceField(validText(), kRow0, 7, "2"), kRow0, "blocked", "0 or 1");
}

TEST(Errors, StepsNotCountingFromZeroByOne) {
  expectError(replaceField(validText(), kRow0 + 1, 1, "2"), kRow0 + 1, "step", "expected step 1");
  expectError(replaceField(validText(), kRow0, 1, "1"), kRow0, "step", "expected step 0");
}

TEST(Errors, UnknownClassName) {
  const std::size_t truthF = 7 + kValuesPerStep + 1;
  expectError(replaceField(validText(), kRow0, truthF, "wall"), kRow0, "truth_F", "contact class");
  expectError(replaceField(validText(), kRow0, truthF + 3, "Hole"), kRow0, "truth_RLC",
              "contact class");
}

TEST(Errors, TruncatedLastLine) {
  std::string text = validText();
  text.resize(text.size() - 40);  // cut into the last row, no final newline
  const Error e = expectError(text, kRow0 + 2, "*", "truncated last line");
  EXPECT_GT(e.column, 0u);
}

TEST(Errors, EmptyLineBetweenRows) {
  std::string text = validText();
  const std::string row1 = lineAt(text, kRow0 + 1);
  text = replaceLine(text, kRow0 + 1, "\n" + row1);
  expectError(text, kRow0 + 1, "", "empty line");
}

TEST(Errors, TrailingBlankLinesAreAccepted) {
  RunCsvResult r = parseRunCsv(validText() + "\n\r\n", "t.csv");
  ASSERT_TRUE(r.ok()) << r.errorText();
  EXPECT_EQ(r.value().stepCount(), 3u);
  expectChunkedSame(validText() + "\n\r\n", r);
}

TEST(RunCsvChunked, ValidFilesParseAlikeWhateverTheChunks) {
  RunData run = makeRun(500, true, 12);
  run.extraColumns = {"x_note"};
  for (std::size_t i = 0; i < run.stepCount(); ++i)
    run.extraValues.push_back(i % 3 == 0 ? "" : "n" + std::to_string(i));
  for (const std::string& text :
       {formatRunCsv(run), formatRunCsv(makeRun(1, false)), formatRunCsv(makeRun(40, false, 5))}) {
    RunCsvResult sequential = parseRunCsv(text, "bad.csv");
    ASSERT_TRUE(sequential.ok()) << sequential.errorText();
    expectChunkedSame(text, sequential);
    // Without the final newline, with CRLF and a byte-order mark.
    expectChunkedSame(text.substr(0, text.size() - 1),
                      parseRunCsv(text.substr(0, text.size() - 1), "bad.csv"));
    std::string crlf = "\xEF\xBB\xBF";
    for (char c : text) {
      if (c == '\n') crlf += '\r';
      crlf += c;
    }
    expectChunkedSame(crlf, parseRunCsv(crlf, "bad.csv"));
  }
}

TEST(RunCsvChunked, ChunksStartAtLinesAndCarryTheirFirstStep) {
  const std::string text = formatRunCsv(makeRun(100, true, 2));
  const RunCsvChunks chunks(text, "c.csv", 1000);
  ASSERT_EQ(chunks.error(), nullptr);
  ASSERT_GT(chunks.size(), 5u);
  std::size_t steps = 0;
  std::size_t bytes = 0;
  for (std::size_t i = 0; i < chunks.size(); ++i) {
    EXPECT_EQ(chunks.firstStep(i), steps);
    EXPECT_GE(chunks.bytes(i), i + 1 < chunks.size() ? 1000u : 1u);
    RunCsvResult part = chunks.parse(i);
    ASSERT_TRUE(part.ok()) << part.errorText();
    EXPECT_TRUE(part.value().metadata.empty());
    steps += part.value().stepCount();
    bytes += chunks.bytes(i);
  }
  EXPECT_EQ(steps, 100u);
  EXPECT_EQ(bytes, text.size() - text.find("\nstep,") - 1 - lineAt(text, kHeader).size() - 1);
  // Header only: one empty chunk, and the join reports that there are no rows.
  const std::string headerOnly = text.substr(0, text.find('\n', text.find("\nstep,") + 1) + 1);
  const RunCsvChunks empty(headerOnly, "h.csv", 1000);
  ASSERT_EQ(empty.size(), 1u);
  EXPECT_EQ(empty.bytes(0), 0u);
  EXPECT_TRUE(empty.checkStepCount(0).has_value());
  EXPECT_FALSE(empty.checkStepCount(1).has_value());
}

TEST(RunCsvChunked, FirstErrorInFileOrderWins) {
  std::string text = formatRunCsv(makeRun(300, true, 4));
  const std::size_t early = kRow0 + 20;
  const std::size_t late = kRow0 + 250;
  text = replaceField(text, late, 3, "late");
  text = replaceField(text, early, 5, "early");
  for (std::size_t chunkBytes : kChunkSizes) {
    RunCsvResult r = parseRunCsvParallel(text, "e.csv", 2, chunkBytes);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().line, early);
    EXPECT_TRUE(r.error().message.starts_with("column 'v' (position 5)")) << r.errorText();
  }
  // A wrong step number in the middle is found however the rows are cut.
  std::string steps = formatRunCsv(makeRun(300, true, 4));
  steps = replaceField(steps, kRow0 + 123, 1, "124");
  expectError(steps, kRow0 + 123, "step", "expected step 123");
}

TEST(Errors, MetadataLineAfterHeader) {
  std::string text = validText();
  text = replaceLine(text, kRow0 + 1, "# scene: late\n" + lineAt(text, kRow0 + 1));
  expectError(text, kRow0 + 1, "", "after the header");
}

TEST(Errors, RepeatedMetadataKey) {
  const Error e = expectError("# dt: 0.1\n" + validText(), 4, "", "repeated metadata key");
  EXPECT_NE(e.message.find("line 1"), std::string::npos);
}

TEST(Errors, WrongFormatVersion) {
  std::string text = replaceLine(validText(), 1, "# format: tactile-run 2");
  expectError(text, 1, "", "expected format 'tactile-run 1'");
}

TEST(Errors, MalformedKnownMetadata) {
  expectError(replaceLine(validText(), 3, "# dt: fast"), 3, "", "'dt'");
  expectError(replaceLine(validText(), 3, "# dt: -0.1"), 3, "", "'dt'");
  expectError(replaceLine(validText(), 4, "# start: 1,2"), 4, "", "'start'");
  expectError(replaceLine(validText(), 5, "# goal: 1,b"), 5, "", "'goal'");
  expectError(replaceLine(validText(), 6, "# outcome: maybe"), 6, "", "'outcome'");
  expectError(replaceLine(validText(), 2, "# just a comment"), 2, "", "'# key: value'");
}

TEST(Errors, BomAndCrlfDoNotHideLineNumbers) {
  std::string text = replaceField(validText(), kRow0 + 1, 2, "oops");
  std::string crlf = "\xEF\xBB\xBF";
  for (char c : text) {
    if (c == '\n') crlf += '\r';
    crlf += c;
  }
  expectError(crlf, kRow0 + 1, "x", "'oops'");
}

TEST(Errors, MessageNamesFileLineAndColumn) {
  RunCsvResult r = parseRunCsv(replaceField(validText(), kRow0, 10, "9"), "runs/a.csv");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.errorText(),
            "runs/a.csv:" + std::to_string(kRow0) +
                ": column 'n1' (position 10): expected a normal value in [0, 5], found '9'");
}

TEST(Errors, UnreadableFile) {
  RunCsvResult r = readRunCsv("/nonexistent/dir/run.csv");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errorText().find("/nonexistent/dir/run.csv"), std::string::npos);
  EXPECT_NE(r.error().message.find("cannot open"), std::string::npos);
}

TEST(RunCsv, ProgressIsReportedAndCancelStops) {
  const std::string text = formatRunCsv(makeRun(20000, false));
  std::size_t calls = 0;
  std::size_t last = 0;
  RunCsvResult r = parseRunCsv(text, "p.csv", [&](std::size_t done, std::size_t total) {
    ++calls;
    EXPECT_EQ(total, text.size());
    EXPECT_GE(done, last);
    last = done;
    return true;
  });
  ASSERT_TRUE(r.ok());
  EXPECT_GT(calls, 1u);
  EXPECT_EQ(last, text.size());
  RunCsvResult cancelled =
      parseRunCsv(text, "p.csv", [](std::size_t, std::size_t) { return false; });
  ASSERT_FALSE(cancelled.ok());
  EXPECT_NE(cancelled.error().message.find("cancelled"), std::string::npos);
}

TEST(RunCsv, AtomicWriteLeavesNoFileOnFailure) {
  const auto dir = std::filesystem::temp_directory_path() / "tactile_no_such_dir_xyz";
  std::filesystem::remove_all(dir);
  const Status written = writeRunCsv(makeRun(2, false), dir / "out.csv");
  ASSERT_FALSE(written.ok());
  EXPECT_EQ(written.error().file, (dir / "out.csv").string());
  EXPECT_FALSE(std::filesystem::exists(dir));
}

}  // namespace
}  // namespace tactile

namespace tactile {
namespace {

TEST(FileText, MapsRegularFilesAndReadsEmptyOnes) {
  const auto dir = std::filesystem::temp_directory_path();
  const auto full = dir / "tactile_file_text_full.txt";
  const auto empty = dir / "tactile_file_text_empty.txt";
  ASSERT_TRUE(writeFileAtomically(full, "abc\ndef").ok());
  ASSERT_TRUE(writeFileAtomically(empty, "").ok());
  FileText text;
  ASSERT_TRUE(text.load(full).ok());
  EXPECT_EQ(text.view(), "abc\ndef");
  FileText moved = std::move(text);
  EXPECT_EQ(moved.view(), "abc\ndef");
  ASSERT_TRUE(moved.load(empty).ok());
  EXPECT_EQ(moved.view(), "");
  const Status missing = moved.load(dir / "tactile_no_such_file.txt");
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.errorText(), (dir / "tactile_no_such_file.txt").string() +
                                     ": cannot open: No such file or directory");
  std::filesystem::remove(full);
  std::filesystem::remove(empty);
}

TEST(Errors, EmptyFileOnDisk) {
  const auto path = std::filesystem::temp_directory_path() / "tactile_empty_run.csv";
  ASSERT_TRUE(writeFileAtomically(path, "").ok());
  RunCsvResult r = readRunCsv(path);
  std::filesystem::remove(path);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("empty file"), std::string::npos);
}

// ---- text fields must be UTF-8 (docs/storage.md#text-fields) ----------------------------------

namespace utf8 {

// A small run with two text columns, as text.
std::string textWithExtras(const std::string& noteValue, const std::string& noteName = "x_note") {
  RunData run = makeRun(4, true);
  run.extraColumns = {noteName, "x_who"};
  for (std::size_t i = 0; i < 4; ++i) {
    run.extraValues.push_back(i == 2 ? noteValue : "n" + std::to_string(i));
    run.extraValues.push_back("ann");
  }
  return formatRunCsv(run);
}

// Line of the row of step `step` in textWithExtras (its metadata has metadataLineCount() lines).
std::size_t rowLine(std::size_t step) {
  return metadataLineCount() + 2 + step;
}

}  // namespace utf8

TEST(RunCsvUtf8, ValidMultiByteTextIsAccepted) {
  const std::string text = "# note: caf\xC3\xA9 \xE6\x97\xA5\xE6\x9C\xAC \xF0\x9F\xA4\x96\n" +
                           utf8::textWithExtras("\xC3\xA9t\xC3\xA9 \xF0\x9F\x99\x82", "x_\xC3\xA9");
  RunCsvResult r = parseRunCsv(text, "ok.csv");
  ASSERT_TRUE(r.ok()) << r.errorText();
  EXPECT_EQ(r.value().extraColumns[0], "x_\xC3\xA9");
  EXPECT_EQ(r.value().extraValues[4], "\xC3\xA9t\xC3\xA9 \xF0\x9F\x99\x82");
  expectChunkedSame(text, r);
}

TEST(RunCsvUtf8, InvalidMetadataValueNamesLineAndKey) {
  const std::string text = "# note: caf\xC3(\n" + validText();
  const Error e = expectError(text, 1, "", "UTF-8");
  EXPECT_NE(e.message.find("'note'"), std::string::npos) << e.text();
  EXPECT_NE(e.message.find("0xC3"), std::string::npos) << e.text();
}

TEST(RunCsvUtf8, InvalidColumnNameNamesItsPosition) {
  const std::string text = utf8::textWithExtras("fine", "x_n\xFFte");
  const Error e = expectError(text, metadataLineCount() + 1, "x_n\\xFFte", "UTF-8");
  EXPECT_GT(e.column, 0u) << e.text();
  EXPECT_NE(e.text().find("(position " + std::to_string(e.column) + ")"), std::string::npos)
      << e.text();
}

TEST(RunCsvUtf8, InvalidTextFieldNamesLineAndColumnAlsoInChunks) {
  // Each is rejected: lone continuation, overlong forms, a surrogate, above U+10FFFF, a cut
  // sequence, bytes never used in UTF-8.
  for (const std::string bad :
       {"\x80", "\xC0\x80", "\xC1\xBF", "\xE0\x80\x80", "\xED\xA0\x80", "\xF0\x80\x80\x80",
        "\xF4\x90\x80\x80", "\xE2\x82", "ab\xF0\x9F\x99", "\xF5\x80\x80\x80", "\xFF", "\xFE"}) {
    SCOPED_TRACE("bytes of length " + std::to_string(bad.size()));
    // expectError also parses in chunks of 1, 37, 300 bytes and 1 MiB (RunCsvChunks).
    const Error e =
        expectError(utf8::textWithExtras("ok " + bad + " ok"), utf8::rowLine(2), "x_note", "UTF-8");
    EXPECT_GT(e.column, 0u);
  }
}

}  // namespace
}  // namespace tactile

namespace tactile {
namespace {

// Regression: `step` and `blocked` took any std::from_chars integer, so "-0", "01", "00" and "001"
// imported. They are integer literals: digits only, no sign, no leading zero.
TEST(Errors, StepAndBlockedAreIntegerLiteralsWithoutSignOrLeadingZero) {
  for (const char* bad : {"00", "01", "001", "-0", "-1", "+1", "1.0", "0x1", " 0", "0 "}) {
    SCOPED_TRACE(bad);
    expectError(replaceField(validText(), kRow0 + 1, 7, bad), kRow0 + 1, "blocked", "0 or 1");
  }
  for (const char* bad : {"-0", "00", "01", "001", "+0"}) {
    SCOPED_TRACE(bad);
    // Row 0 carries step 0: "-0" and "00" have the right value but not the right spelling.
    const Error e = expectError(replaceField(validText(), kRow0, 1, bad), kRow0, "step",
                                "no sign, no leading zero");
    EXPECT_EQ(e.column, 1u);
  }
  const Error e =
      expectError(replaceField(validText(), kRow0 + 1, 1, "01"), kRow0 + 1, "step", "found '01'");
  EXPECT_EQ(e.column, 1u);
  // The plain literals still parse.
  RunCsvResult ok = parseRunCsv(replaceField(validText(), kRow0 + 1, 7, "1"), "ok.csv");
  ASSERT_TRUE(ok.ok()) << ok.errorText();
  EXPECT_TRUE(ok.value().blocked[1]);
}

// Regression: 1e-400 was reported as "expected a finite number (no NaN or infinity)".
TEST(Errors, UnderflowAndOverflowAreNamed) {
  for (const char* tiny : {"1e-400", "-2e-324", "0.1e-9999"}) {
    SCOPED_TRACE(tiny);
    expectError(replaceField(validText(), kRow0, 2, tiny), kRow0, "x", "underflows");
  }
  for (const char* huge : {"1e400", "-1e309", "1e99999"}) {
    SCOPED_TRACE(huge);
    const Error e = expectError(replaceField(validText(), kRow0, 2, huge), kRow0, "x", "overflows");
    EXPECT_EQ(e.message.find("underflows"), std::string::npos) << e.message;
  }
  // A subnormal is a finite double and reads back exactly.
  RunCsvResult ok = parseRunCsv(replaceField(validText(), kRow0, 2, "4.9e-324"), "ok.csv");
  ASSERT_TRUE(ok.ok()) << ok.errorText();
  EXPECT_EQ(ok.value().x[0], std::numeric_limits<double>::denorm_min());
}

// Regression: a form feed after a number was shown raw ("found '0'" on a terminal).
TEST(Errors, ControlCharactersAreShownAndNamed) {
  Error e = expectError(replaceField(validText(), kRow0, 8, "0\f"), kRow0, "n0", "'0\\x0C'");
  EXPECT_NE(e.message.find("form feed (U+000C) at byte 2"), std::string::npos) << e.message;
  e = expectError(replaceField(validText(), kRow0, 2, "\t1"), kRow0, "x", "a tab (U+0009)");
  e = expectError(replaceField(validText(), kRow0, 7, std::string("1\0", 2)), kRow0, "blocked",
                  "a NUL byte");
  e = expectError(replaceField(validText(), kRow0, 3, "1\xE9"), kRow0, "y", "'1\\xE9'");
}

}  // namespace
}  // namespace tactile
