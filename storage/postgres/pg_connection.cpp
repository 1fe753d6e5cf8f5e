#include "storage/postgres/pg_connection.h"

#include <libpq-fe.h>

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cstring>
#include <map>
#include <vector>

namespace tactile::storage::db {
namespace {

// Type oids of the built-in types (PostgreSQL's pg_type.dat; fixed since 7.x).
constexpr Oid kBool = 16;
constexpr Oid kBytea = 17;
constexpr Oid kInt8 = 20;
constexpr Oid kInt2 = 21;
constexpr Oid kInt4 = 23;
constexpr Oid kText = 25;
constexpr Oid kFloat4 = 700;
constexpr Oid kFloat8 = 701;
constexpr Oid kNumeric = 1700;

// The lock every writing transaction takes first (pg_advisory_xact_lock), so that writers queue as
// they do on an SQLite file and a read-then-write (the newest-wins label edit, a name check) sees
// no other writer between its read and its write. Any fixed 64-bit number; "tactile" in ASCII.
constexpr const char* kBeginWrite = "BEGIN; SELECT pg_advisory_xact_lock(32772479565399397)";

std::uint64_t toBig64(std::uint64_t v) {
  if constexpr (std::endian::native == std::endian::little) return __builtin_bswap64(v);
  return v;
}
std::uint32_t toBig32(std::uint32_t v) {
  if constexpr (std::endian::native == std::endian::little) return __builtin_bswap32(v);
  return v;
}
std::uint16_t toBig16(std::uint16_t v) {
  if constexpr (std::endian::native == std::endian::little) return __builtin_bswap16(v);
  return v;
}

std::int64_t readBig(const char* p, int bytes) {
  switch (bytes) {
    case 1:
      return static_cast<std::int64_t>(static_cast<unsigned char>(p[0]));
    case 2: {
      std::uint16_t v;
      std::memcpy(&v, p, 2);
      return static_cast<std::int16_t>(toBig16(v));
    }
    case 4: {
      std::uint32_t v;
      std::memcpy(&v, p, 4);
      return static_cast<std::int32_t>(toBig32(v));
    }
    default: {
      std::uint64_t v;
      std::memcpy(&v, p, 8);
      return static_cast<std::int64_t>(toBig64(v));
    }
  }
}

// A NUMERIC in binary format (sum() of integers gives one): base-10000 digits with a weight.
double numericValue(const char* p, int bytes) {
  if (bytes < 8) return 0.0;
  const auto digits = static_cast<int>(readBig(p, 2));
  const auto weight = static_cast<int>(readBig(p + 2, 2));
  const auto sign = static_cast<std::uint16_t>(readBig(p + 4, 2));
  if (sign == 0xC000 || bytes < 8 + 2 * digits) return 0.0;  // NaN: never from our columns
  double value = 0.0;
  for (int i = 0; i < digits; ++i) {
    value = value * 10000.0 + static_cast<double>(readBig(p + 8 + 2 * i, 2));
  }
  for (int i = digits - 1; i < weight; ++i)
    value *= 10000.0;
  for (int i = weight; i < digits - 1; ++i)
    value /= 10000.0;
  return sign == 0x4000 ? -value : value;
}

std::string trimmed(const char* text) {
  std::string s = text != nullptr ? text : "";
  while (!s.empty() && (s.back() == '\n' || s.back() == ' '))
    s.pop_back();
  // libpq's messages may span lines (a DETAIL, a HINT): one line for the user, without the
  // severity the server puts first.
  std::replace(s.begin(), s.end(), '\n', ' ');
  std::replace(s.begin(), s.end(), '\t', ' ');
  s.erase(std::unique(s.begin(), s.end(), [](char a, char b) { return a == ' ' && b == ' '; }),
          s.end());
  for (const char* severity : {"FATAL:  ", "ERROR:  "}) {
    if (const std::size_t at = s.find(severity); at != std::string::npos) s.erase(at, 8);
  }
  return s;
}

// A statement's or connection's failure as one line, with the SQLSTATE kept for callers.
// What a refused statement needed, from the table the server names: "; the role 'anna' lacks the
// admin right (importing, renaming and deleting runs)".
std::string missingRight(PGconn* conn, const std::string& text) {
  const std::string_view marker = "for table ";
  const std::size_t at = text.find(marker);
  if (at == std::string::npos) return {};
  const std::string table = text.substr(at + marker.size());
  std::string right = "admin right (importing, renaming and deleting runs)";
  if (table == "models" || table == "sweeps" || table == "sweep_cells" || table == "sweep_claims") {
    right = "researcher right (keeping models and sweeps)";
  } else if (table.starts_with("label_") || table == "assignments") {
    right = "annotator right (editing labels)";
  }
  const char* user = PQuser(conn);
  return "; the role '" + std::string(user == nullptr ? "" : user) + "' lacks the " + right +
         " (tactile db grant)";
}

[[noreturn]] void failResult(const std::string& name, PGconn* conn, const PGresult* result,
                             const std::string& what, std::string_view sql) {
  std::string state;
  std::string text;
  if (result != nullptr) {
    if (const char* s = PQresultErrorField(result, PG_DIAG_SQLSTATE)) state = s;
    if (const char* m = PQresultErrorField(result, PG_DIAG_MESSAGE_PRIMARY)) text = m;
  }
  if (text.empty()) text = trimmed(PQerrorMessage(conn));
  if (PQstatus(conn) == CONNECTION_BAD) {
    throw DbError(name, "lost the connection to the server (" + text + ")", "08006");
  }
  std::string message = what + ": " + text;
  if (state == "42501") message = "refused by the server: " + text + missingRight(conn, text);
  if (!sql.empty() && state != "42501") {
    message += " (in: " + std::string(sql.substr(0, 200)) + ")";
  }
  throw DbError(name, message, state);
}

struct ResultDeleter {
  void operator()(PGresult* r) const { PQclear(r); }
};
using ResultPtr = std::unique_ptr<PGresult, ResultDeleter>;

class PgConnection;

// A bound parameter: its type and its bytes in binary format (or null).
struct Parameter {
  Oid type = 0;
  bool null = true;
  std::string bytes;
};

class PgStatement : public StatementBackend {
 public:
  // `streamed`: rows come from COPY (...) TO STDOUT in binary format, one at a time, instead of a
  // result held whole in memory (ConnectionBackend::prepareStreamed).
  PgStatement(PgConnection& connection, std::string_view sql, bool streamed = false);
  // Frees the statement's server-side copies, so that a long session (the workbench) does not
  // gather one per statement ever made.
  ~PgStatement() override;
  PgStatement(const PgStatement&) = delete;
  PgStatement& operator=(const PgStatement&) = delete;

  void bindInt(int index, std::int64_t value) override {
    Parameter& p = at(index);
    p.type = kInt8;
    p.null = false;
    const std::uint64_t big = toBig64(static_cast<std::uint64_t>(value));
    p.bytes.assign(reinterpret_cast<const char*>(&big), 8);
  }
  void bindDouble(int index, double value) override {
    Parameter& p = at(index);
    p.type = kFloat8;
    p.null = false;
    const std::uint64_t big = toBig64(std::bit_cast<std::uint64_t>(value));
    p.bytes.assign(reinterpret_cast<const char*>(&big), 8);
  }
  void bindText(int index, std::string_view text) override {
    Parameter& p = at(index);
    p.type = kText;
    p.null = false;
    p.bytes.assign(text.data(), text.size());
  }
  void bindBlob(int index, const void* data, std::size_t bytes) override {
    Parameter& p = at(index);
    p.type = kBytea;
    p.null = false;
    p.bytes.assign(static_cast<const char*>(data), bytes);
  }
  void bindNull(int index) override {
    Parameter& p = at(index);
    p.null = true;
    p.bytes.clear();
  }

  bool step() override;
  void reset() override {
    if (streaming_) endStream();
    result_.reset();
    row_ = -1;
    rows_ = 0;
  }

  std::int64_t columnInt(int column) const override {
    if (isNull(column)) return 0;
    const char* v = valueAt(column);
    const int n = lengthAt(column);
    switch (typeAt(column)) {
      case kBool:
      case kInt2:
      case kInt4:
      case kInt8:
        return readBig(v, n);
      case kFloat4:
      case kFloat8:
      case kNumeric:
        return static_cast<std::int64_t>(columnDouble(column));
      default: {
        std::int64_t out = 0;
        std::from_chars(v, v + n, out);
        return out;
      }
    }
  }
  double columnDouble(int column) const override {
    if (isNull(column)) return 0.0;
    const char* v = valueAt(column);
    switch (typeAt(column)) {
      case kFloat8: {
        std::uint64_t bits;
        std::memcpy(&bits, v, 8);
        return std::bit_cast<double>(toBig64(bits));
      }
      case kFloat4: {
        std::uint32_t bits;
        std::memcpy(&bits, v, 4);
        return std::bit_cast<float>(toBig32(bits));
      }
      case kBool:
      case kInt2:
      case kInt4:
      case kInt8:
        return static_cast<double>(readBig(v, lengthAt(column)));
      case kNumeric:
        return numericValue(v, lengthAt(column));
      default:
        return 0.0;
    }
  }
  std::string_view columnText(int column) const override {
    if (isNull(column)) return {};
    const char* v = valueAt(column);
    const int n = lengthAt(column);
    switch (typeAt(column)) {
      case kBool:
      case kInt2:
      case kInt4:
      case kInt8: {
        // As SQLite gives an integer column's text: its decimal digits.
        char digits[24];
        const auto end = std::to_chars(digits, digits + sizeof digits, readBig(v, n)).ptr;
        textBuffer_.assign(digits, end);
        return textBuffer_;
      }
      default:
        return {v, static_cast<std::size_t>(n)};
    }
  }
  const void* columnBlob(int column) const override {
    return isNull(column) ? nullptr : valueAt(column);
  }
  std::size_t columnBytes(int column) const override {
    return isNull(column) ? 0 : static_cast<std::size_t>(lengthAt(column));
  }
  bool columnIsNull(int column) const override { return isNull(column); }

 private:
  Parameter& at(int index) {
    if (index < 1 || index > static_cast<int>(parameters_.size())) {
      throw DbError("parameter " + std::to_string(index) + " out of range (in: " + sql_ + ")");
    }
    reset();
    return parameters_[static_cast<std::size_t>(index - 1)];
  }
  bool isNull(int column) const {
    if (streamed_) {
      return !streaming_ || column < 0 || column >= static_cast<int>(fields_.size()) ||
             fields_[static_cast<std::size_t>(column)].second < 0;
    }
    return result_ == nullptr || row_ < 0 || row_ >= rows_ ||
           PQgetisnull(result_.get(), row_, column) != 0;
  }
  // The current row's value of `column` in binary format, its length and its type.
  const char* valueAt(int column) const {
    if (streamed_) return fields_[static_cast<std::size_t>(column)].first;
    return PQgetvalue(result_.get(), row_, column);
  }
  int lengthAt(int column) const {
    if (streamed_) return fields_[static_cast<std::size_t>(column)].second;
    return PQgetlength(result_.get(), row_, column);
  }
  Oid typeAt(int column) const {
    if (streamed_) return column < static_cast<int>(types_.size()) ? types_[column] : 0;
    return PQftype(result_.get(), column);
  }
  // ---- streamed reads ----
  void startStream();
  bool nextStreamRow();
  // Reads what is left of the COPY and its final result; throws when the server reported an error
  // (unless `quiet`).
  void endStream(bool quiet = true);
  // The server-side statement for the parameters' current types (prepared on first use).
  const std::string& prepared();

  PgConnection& connection_;
  std::string sql_;  // with $N parameters
  std::string original_;
  std::vector<Parameter> parameters_;
  std::map<std::vector<Oid>, std::string> preparedByTypes_;
  ResultPtr result_;
  int rows_ = 0;
  int row_ = -1;
  mutable std::string textBuffer_;
  // Streamed: the columns' types (from describing the prepared statement), the COPY row buffer and
  // its fields (value, length; -1 for NULL).
  bool streamed_ = false;
  bool streaming_ = false;
  bool sawHeader_ = false;
  std::vector<Oid> types_;
  char* buffer_ = nullptr;
  std::vector<std::pair<const char*, int>> fields_;
};

// COPY ... FROM STDIN in binary format: rows are encoded here and sent in large pieces.
class PgRowWriter : public RowWriterBackend {
 public:
  PgRowWriter(PgConnection& connection, std::string_view table, std::string_view columns,
              int count);
  ~PgRowWriter() override;

  void bindInt(int index, std::int64_t value) override {
    Field& f = field(index);
    f.null = false;
    const int width = widths_[static_cast<std::size_t>(index - 1)];
    if (width == 8) {
      const std::uint64_t big = toBig64(static_cast<std::uint64_t>(value));
      f.bytes.assign(reinterpret_cast<const char*>(&big), 8);
    } else if (width == 4) {
      const std::uint32_t big = toBig32(static_cast<std::uint32_t>(value));
      f.bytes.assign(reinterpret_cast<const char*>(&big), 4);
    } else if (width == 2) {
      const std::uint16_t big = toBig16(static_cast<std::uint16_t>(value));
      f.bytes.assign(reinterpret_cast<const char*>(&big), 2);
    } else {
      f.bytes.assign(1, static_cast<char>(value != 0));
    }
  }
  void bindDouble(int index, double value) override {
    Field& f = field(index);
    f.null = false;
    const std::uint64_t big = toBig64(std::bit_cast<std::uint64_t>(value));
    f.bytes.assign(reinterpret_cast<const char*>(&big), 8);
  }
  void bindText(int index, std::string_view text) override {
    Field& f = field(index);
    f.null = false;
    f.bytes.assign(text.data(), text.size());
  }
  void bindBlob(int index, const void* data, std::size_t bytes) override {
    Field& f = field(index);
    f.null = false;
    f.bytes.assign(static_cast<const char*>(data), bytes);
  }
  void bindNull(int index) override { field(index).null = true; }
  bool step() override { return false; }
  void reset() override {}
  std::int64_t columnInt(int) const override { return 0; }
  double columnDouble(int) const override { return 0; }
  std::string_view columnText(int) const override { return {}; }
  const void* columnBlob(int) const override { return nullptr; }
  std::size_t columnBytes(int) const override { return 0; }
  bool columnIsNull(int) const override { return true; }

  void add() override;
  void finish() override;

 private:
  struct Field {
    bool null = true;
    std::string bytes;
  };
  Field& field(int index) {
    if (index < 1 || index > static_cast<int>(fields_.size())) {
      throw DbError("column " + std::to_string(index) + " out of range in a bulk insert");
    }
    return fields_[static_cast<std::size_t>(index - 1)];
  }
  void flush();
  void put16(std::uint16_t v) {
    const std::uint16_t big = toBig16(v);
    buffer_.append(reinterpret_cast<const char*>(&big), 2);
  }
  void put32(std::uint32_t v) {
    const std::uint32_t big = toBig32(v);
    buffer_.append(reinterpret_cast<const char*>(&big), 4);
  }

  PgConnection& connection_;
  std::vector<Field> fields_;
  std::vector<int> widths_;  // bytes of each integer column's type (8, 4, 2 or 1 for bool)
  std::string buffer_;
  bool open_ = false;
};

class PgConnection : public ConnectionBackend {
 public:
  PgConnection(PGconn* conn, std::string name) : conn_(conn), name_(std::move(name)) {}
  ~PgConnection() override { PQfinish(conn_); }
  PgConnection(const PgConnection&) = delete;
  PgConnection& operator=(const PgConnection&) = delete;

  Engine engine() const override { return Engine::Postgres; }
  const std::string& name() const override { return name_; }
  std::unique_ptr<StatementBackend> prepare(std::string_view sql) override {
    return std::make_unique<PgStatement>(*this, sql);
  }
  std::unique_ptr<StatementBackend> prepareStreamed(std::string_view sql) override {
    return std::make_unique<PgStatement>(*this, sql, true);
  }
  std::unique_ptr<RowWriterBackend> rowWriter(std::string_view table, std::string_view columns,
                                              int count) override {
    return std::make_unique<PgRowWriter>(*this, table, columns, count);
  }
  void exec(std::string_view sql) override {
    const std::string text(sql);
    ResultPtr result(PQexec(conn_, text.c_str()));
    const ExecStatusType status = PQresultStatus(result.get());
    if (status != PGRES_COMMAND_OK && status != PGRES_TUPLES_OK) {
      failResult(name_, conn_, result.get(), "statement failed", text);
    }
    noteChanges(result.get());
  }
  void begin() override { exec(kBeginWrite); }
  void beginRowLocking() override { exec("BEGIN"); }
  void commit() override {
    // COMMIT of a failed transaction rolls it back without an error: say so instead.
    if (PQtransactionStatus(conn_) == PQTRANS_INERROR) {
      rollback();
      throw DbError(name_, "a statement of the transaction failed; nothing of it was stored");
    }
    exec("COMMIT");
  }
  void rollback() noexcept override {
    if (PQtransactionStatus(conn_) == PQTRANS_IDLE) return;
    PQclear(PQexec(conn_, "ROLLBACK"));
  }
  std::int64_t changes() const override { return changes_; }
  void beginSnapshot() override { exec("BEGIN ISOLATION LEVEL REPEATABLE READ READ ONLY"); }
  void endSnapshot() noexcept override {
    if (PQtransactionStatus(conn_) != PQTRANS_IDLE) PQclear(PQexec(conn_, "COMMIT"));
  }
  bool inTransaction() const override { return PQtransactionStatus(conn_) != PQTRANS_IDLE; }
  bool changedSinceLastPoll(std::string_view channel) override {
    if (std::find(listening_.begin(), listening_.end(), channel) == listening_.end()) {
      exec("LISTEN " + std::string(channel));
      listening_.emplace_back(channel);
      return false;
    }
    // Reads what the server sent without a round trip.
    if (PQconsumeInput(conn_) == 0 || PQstatus(conn_) == CONNECTION_BAD) {
      throw DbError(name_, "lost the connection to the server: " + trimmed(PQerrorMessage(conn_)),
                    "08006");
    }
    bool changed = false;
    while (PGnotify* note = PQnotifies(conn_)) {
      changed = changed || channel == note->relname;
      PQfreemem(note);
    }
    return changed;
  }

  PGconn* handle() const { return conn_; }
  // The integer widths of a bulk insert's columns, asked of the catalogue once per session.
  const std::vector<int>* columnWidths(const std::string& key) const {
    const auto it = widths_.find(key);
    return it == widths_.end() ? nullptr : &it->second;
  }
  void rememberColumnWidths(const std::string& key, std::vector<int> widths) {
    widths_[key] = std::move(widths);
  }
  std::string nextStatementName() { return "tactile_" + std::to_string(++statements_); }
  void noteChanges(const PGresult* result) {
    const char* tuples = PQcmdTuples(const_cast<PGresult*>(result));
    if (tuples != nullptr && *tuples != '\0') {
      std::int64_t n = 0;
      std::from_chars(tuples, tuples + std::strlen(tuples), n);
      changes_ = n;
    }
  }

 private:
  PGconn* conn_ = nullptr;
  std::vector<std::string> listening_;  // channels LISTENed to
  std::string name_;
  std::int64_t changes_ = 0;
  std::uint64_t statements_ = 0;
  std::map<std::string, std::vector<int>> widths_;
};

PgStatement::PgStatement(PgConnection& connection, std::string_view sql, bool streamed)
    : connection_(connection), original_(sql), streamed_(streamed) {
  int count = 0;
  sql_ = numberedParameters(sql, count);
  parameters_.resize(static_cast<std::size_t>(count));
}

PgStatement::~PgStatement() {
  result_.reset();
  if (streaming_) endStream();
  PGconn* conn = connection_.handle();
  if (PQstatus(conn) != CONNECTION_OK) return;
  for (const auto& [types, name] : preparedByTypes_) {
    const std::string sql = "DEALLOCATE " + name;
    PQclear(PQexec(conn, sql.c_str()));  // in a failed transaction it fails: the session ends it
  }
}

const std::string& PgStatement::prepared() {
  std::vector<Oid> types(parameters_.size());
  for (std::size_t i = 0; i < parameters_.size(); ++i)
    types[i] = parameters_[i].null ? 0 : parameters_[i].type;
  auto it = preparedByTypes_.find(types);
  if (it != preparedByTypes_.end()) return it->second;
  std::string name = connection_.nextStatementName();
  ResultPtr result(PQprepare(connection_.handle(), name.c_str(), sql_.c_str(),
                             static_cast<int>(types.size()), types.data()));
  if (PQresultStatus(result.get()) != PGRES_COMMAND_OK) {
    failResult(connection_.name(), connection_.handle(), result.get(), "cannot prepare statement",
               original_);
  }
  return preparedByTypes_.emplace(std::move(types), std::move(name)).first->second;
}

bool PgStatement::step() {
  if (streamed_) {
    if (!streaming_ && row_ >= 0) return false;  // read to its end: reset() starts it again
    if (!streaming_) startStream();
    return nextStreamRow();
  }
  if (result_ == nullptr) {
    const std::string& name = prepared();
    const std::size_t n = parameters_.size();
    std::vector<const char*> values(n);
    std::vector<int> lengths(n);
    std::vector<int> formats(n, 1);
    for (std::size_t i = 0; i < n; ++i) {
      values[i] = parameters_[i].null ? nullptr : parameters_[i].bytes.data();
      lengths[i] = static_cast<int>(parameters_[i].bytes.size());
    }
    result_.reset(PQexecPrepared(connection_.handle(), name.c_str(), static_cast<int>(n),
                                 values.data(), lengths.data(), formats.data(), 1));
    const ExecStatusType status = PQresultStatus(result_.get());
    if (status != PGRES_TUPLES_OK && status != PGRES_COMMAND_OK) {
      ResultPtr failed = std::move(result_);
      failResult(connection_.name(), connection_.handle(), failed.get(), "statement failed",
                 original_);
    }
    connection_.noteChanges(result_.get());
    rows_ = status == PGRES_TUPLES_OK ? PQntuples(result_.get()) : 0;
    row_ = -1;
  }
  if (row_ < rows_) ++row_;
  return row_ < rows_;
}

// COPY takes no parameters: they are written into the query as literals. Only integers, numbers,
// text and NULL are needed by the reads that stream; text goes through libpq's own quoting.
void PgStatement::startStream() {
  PGconn* conn = connection_.handle();
  if (types_.empty()) {
    ResultPtr described(PQdescribePrepared(conn, prepared().c_str()));
    if (PQresultStatus(described.get()) != PGRES_COMMAND_OK) {
      failResult(connection_.name(), conn, described.get(), "cannot describe statement", original_);
    }
    for (int c = 0; c < PQnfields(described.get()); ++c)
      types_.push_back(PQftype(described.get(), c));
  }
  std::string query = "COPY (";
  for (std::size_t i = 0; i < sql_.size(); ++i) {
    if (sql_[i] != '$' || i + 1 >= sql_.size() || sql_[i + 1] < '0' || sql_[i + 1] > '9') {
      query += sql_[i];
      continue;
    }
    std::size_t number = 0;
    while (i + 1 < sql_.size() && sql_[i + 1] >= '0' && sql_[i + 1] <= '9')
      number = number * 10 + static_cast<std::size_t>(sql_[++i] - '0');
    const Parameter& p = parameters_.at(number - 1);
    if (p.null) {
      query += "NULL";
    } else if (p.type == kInt8) {
      query += std::to_string(readBig(p.bytes.data(), 8));
    } else if (p.type == kFloat8) {
      std::uint64_t bits;
      std::memcpy(&bits, p.bytes.data(), 8);
      char digits[32];
      const auto end =
          std::to_chars(digits, digits + sizeof digits, std::bit_cast<double>(toBig64(bits))).ptr;
      query += "'" + std::string(digits, end) + "'::float8";
    } else if (p.type == kText) {
      char* quoted = PQescapeLiteral(conn, p.bytes.data(), p.bytes.size());
      if (quoted == nullptr) {
        throw DbError(connection_.name(),
                      "cannot quote a parameter: " + trimmed(PQerrorMessage(conn)) +
                          " (in: " + original_ + ")");
      }
      query += quoted;
      PQfreemem(quoted);
    } else {
      throw DbError(connection_.name(),
                    "a streamed read takes no blob parameters (in: " + original_ + ")");
    }
  }
  query += ") TO STDOUT (FORMAT binary)";
  ResultPtr started(PQexec(conn, query.c_str()));
  if (PQresultStatus(started.get()) != PGRES_COPY_OUT) {
    failResult(connection_.name(), conn, started.get(), "statement failed", original_);
  }
  streaming_ = true;
  sawHeader_ = false;
  row_ = 0;
}

bool PgStatement::nextStreamRow() {
  PGconn* conn = connection_.handle();
  const auto malformed = [&] {
    endStream();
    throw DbError(connection_.name(), "the server sent a malformed row (in: " + original_ + ")");
  };
  for (;;) {
    if (buffer_ != nullptr) {
      PQfreemem(buffer_);
      buffer_ = nullptr;
    }
    fields_.clear();
    const int bytes = PQgetCopyData(conn, &buffer_, 0);
    if (bytes == -1) {
      endStream(false);
      return false;
    }
    if (bytes < 0) {
      streaming_ = false;
      failResult(connection_.name(), conn, nullptr, "reading rows failed", original_);
    }
    const char* p = buffer_;
    const char* end = buffer_ + bytes;
    // The file header ("PGCOPY\n\377\r\n\0", flags, extension) comes before the first row.
    if (!sawHeader_) {
      static constexpr char kSignature[] = "PGCOPY\n\377\r\n";
      if (end - p < 19 || std::memcmp(p, kSignature, 11) != 0) malformed();
      const auto extension = readBig(p + 15, 4);
      if (extension < 0 || end - p < 19 + extension) malformed();
      p += 19 + extension;
      sawHeader_ = true;
      if (p == end) continue;
    }
    if (end - p < 2) malformed();
    const auto count = readBig(p, 2);
    p += 2;
    if (count == -1) continue;  // the trailer; the end of the data follows
    if (count < 0) malformed();
    for (std::int64_t c = 0; c < count; ++c) {
      if (end - p < 4) malformed();
      const auto length = static_cast<int>(readBig(p, 4));
      p += 4;
      if (length < -1 || (length > 0 && end - p < length)) malformed();
      fields_.emplace_back(length < 0 ? nullptr : p, length);
      if (length > 0) p += length;
    }
    ++row_;
    return true;
  }
}

void PgStatement::endStream(bool quiet) {
  PGconn* conn = connection_.handle();
  streaming_ = false;
  fields_.clear();
  if (buffer_ != nullptr) {
    PQfreemem(buffer_);
    buffer_ = nullptr;
  }
  // What is left of the rows is read and dropped: cancelling would fail the caller's transaction.
  for (;;) {
    char* rest = nullptr;
    const int bytes = PQgetCopyData(conn, &rest, 0);
    if (rest != nullptr) PQfreemem(rest);
    if (bytes < 0) break;
  }
  ResultPtr failed;
  while (PGresult* r = PQgetResult(conn)) {
    if (PQresultStatus(r) != PGRES_COMMAND_OK && failed == nullptr) {
      failed.reset(r);
    } else {
      PQclear(r);
    }
  }
  if (failed != nullptr && !quiet) {
    failResult(connection_.name(), conn, failed.get(), "statement failed", original_);
  }
}

PgRowWriter::PgRowWriter(PgConnection& connection, std::string_view table, std::string_view columns,
                         int count)
    : connection_(connection), fields_(static_cast<std::size_t>(count)) {
  // Binary COPY wants each integer in its column's own width: ask the catalogue.
  const std::string tableName(table);
  std::vector<std::string> names;
  {
    std::string current;
    for (const char ch : columns) {
      if (ch == ',') {
        names.push_back(current);
        current.clear();
      } else if (ch != ' ') {
        current += ch;
      }
    }
    names.push_back(current);
  }
  if (static_cast<int>(names.size()) != count) {
    throw DbError(connection.name(), "a bulk insert into " + tableName + " names " +
                                         std::to_string(names.size()) + " columns, not " +
                                         std::to_string(count));
  }
  const std::string key = tableName + "(" + std::string(columns) + ")";
  if (const std::vector<int>* known = connection.columnWidths(key)) {
    widths_ = *known;
  } else {
    for (const std::string& column : names) {
      const std::string sql = "SELECT atttypid FROM pg_attribute WHERE attrelid = '" + tableName +
                              "'::regclass AND attname = '" + column + "'";
      ResultPtr result(
          PQexecParams(connection.handle(), sql.c_str(), 0, nullptr, nullptr, nullptr, nullptr, 0));
      if (PQresultStatus(result.get()) != PGRES_TUPLES_OK || PQntuples(result.get()) != 1) {
        failResult(connection.name(), connection.handle(), result.get(),
                   "cannot find column " + column + " of table " + tableName, sql);
      }
      const Oid type = static_cast<Oid>(std::stoul(PQgetvalue(result.get(), 0, 0)));
      widths_.push_back(type == kInt4 ? 4 : type == kInt2 ? 2 : type == kBool ? 1 : 8);
    }
    connection.rememberColumnWidths(key, widths_);
  }
  const std::string copy =
      "COPY " + tableName + "(" + std::string(columns) + ") FROM STDIN WITH (FORMAT binary)";
  ResultPtr started(PQexec(connection.handle(), copy.c_str()));
  if (PQresultStatus(started.get()) != PGRES_COPY_IN) {
    failResult(connection.name(), connection.handle(), started.get(), "cannot start a bulk insert",
               copy);
  }
  open_ = true;
  static constexpr char kSignature[] = "PGCOPY\n\377\r\n";  // 11 bytes with its NUL
  buffer_.append(kSignature, 11);
  put32(0);  // flags
  put32(0);  // header extension length
}

PgRowWriter::~PgRowWriter() {
  if (!open_) return;
  // Abandoned (an exception on the way): end the COPY with an error, so the transaction fails and
  // the connection can be used for its ROLLBACK.
  PQputCopyEnd(connection_.handle(), "abandoned");
  while (PGresult* r = PQgetResult(connection_.handle()))
    PQclear(r);
}

void PgRowWriter::add() {
  put16(static_cast<std::uint16_t>(fields_.size()));
  for (const Field& f : fields_) {
    if (f.null) {
      put32(0xffffffffU);
    } else {
      put32(static_cast<std::uint32_t>(f.bytes.size()));
      buffer_ += f.bytes;
    }
  }
  if (buffer_.size() >= (std::size_t{1} << 20)) flush();
}

void PgRowWriter::flush() {
  if (buffer_.empty()) return;
  if (PQputCopyData(connection_.handle(), buffer_.data(), static_cast<int>(buffer_.size())) != 1) {
    failResult(connection_.name(), connection_.handle(), nullptr, "bulk insert failed", {});
  }
  buffer_.clear();
}

void PgRowWriter::finish() {
  if (!open_) return;
  put16(0xffff);  // trailer
  flush();
  open_ = false;
  if (PQputCopyEnd(connection_.handle(), nullptr) != 1) {
    failResult(connection_.name(), connection_.handle(), nullptr, "bulk insert failed", {});
  }
  ResultPtr result(PQgetResult(connection_.handle()));
  const bool ok = PQresultStatus(result.get()) == PGRES_COMMAND_OK;
  if (ok) connection_.noteChanges(result.get());
  std::string state;
  if (!ok) {
    while (PGresult* r = PQgetResult(connection_.handle()))
      PQclear(r);
    failResult(connection_.name(), connection_.handle(), result.get(), "bulk insert failed", {});
  }
  while (PGresult* r = PQgetResult(connection_.handle()))
    PQclear(r);
}

void ignoreNotice(void*, const char*) {}

}  // namespace

bool isServerAddress(std::string_view address) {
  if (address.starts_with("postgresql://") || address.starts_with("postgres://")) return true;
  // A libpq key=value string ("host=/run/pg dbname=lab", "service=lab"): its first word is one of
  // libpq's connection keywords followed by '='.
  const std::size_t eq = address.find('=');
  if (eq == std::string_view::npos) return false;
  const std::string_view key = address.substr(0, eq);
  for (const std::string_view known :
       {"host", "hostaddr", "port", "dbname", "user", "service", "sslmode", "options",
        "application_name", "connect_timeout", "passfile"}) {
    if (key == known) return true;
  }
  return false;
}

std::string redactedAddress(std::string_view address) {
  std::string out(address);
  if (out.starts_with("postgresql://") || out.starts_with("postgres://")) {
    const std::size_t scheme = out.find("://") + 3;
    const std::size_t authorityEnd = std::min(out.find_first_of("/?", scheme), out.size());
    const std::size_t at = out.rfind('@', authorityEnd);
    if (at != std::string::npos && at >= scheme) {
      const std::size_t colon = out.find(':', scheme);
      if (colon != std::string::npos && colon < at) out.replace(colon + 1, at - colon - 1, "***");
    }
  }
  // password=... as a query parameter or a key=value pair.
  for (std::size_t pos = 0; (pos = out.find("password=", pos)) != std::string::npos;) {
    const bool atKey =
        pos == 0 || out[pos - 1] == '?' || out[pos - 1] == '&' || out[pos - 1] == ' ';
    pos += 9;
    if (!atKey) continue;
    std::size_t end = pos;
    if (end < out.size() && out[end] == '\'') {
      end = out.find('\'', end + 1);
      end = end == std::string::npos ? out.size() : end + 1;
    } else {
      while (end < out.size() && out[end] != '&' && out[end] != ' ')
        ++end;
    }
    out.replace(pos, end - pos, "***");
  }
  return out;
}

std::string numberedParameters(std::string_view sql, int& count) {
  std::string out;
  out.reserve(sql.size() + 16);
  int next = 0;
  int highest = 0;
  for (std::size_t i = 0; i < sql.size(); ++i) {
    const char ch = sql[i];
    if (ch == '\'' || ch == '"') {  // a literal or quoted name, with doubled quotes inside
      std::size_t j = i + 1;
      while (j < sql.size()) {
        if (sql[j] == ch) {
          if (j + 1 < sql.size() && sql[j + 1] == ch) {
            j += 2;
            continue;
          }
          break;
        }
        ++j;
      }
      out.append(sql.substr(i, j - i + 1));
      i = j;
    } else if (ch == '-' && i + 1 < sql.size() && sql[i + 1] == '-') {
      const std::size_t end = std::min(sql.find('\n', i), sql.size());
      out.append(sql.substr(i, end - i));
      i = end - 1;
    } else if (ch == '?') {
      std::size_t j = i + 1;
      int number = 0;
      while (j < sql.size() && sql[j] >= '0' && sql[j] <= '9')
        number = number * 10 + (sql[j++] - '0');
      if (j == i + 1) number = ++next;
      highest = std::max(highest, number);
      out += '$';
      out += std::to_string(number);
      i = j - 1;
    } else {
      out += ch;
    }
  }
  count = highest;
  return out;
}

Connection connectServer(const std::string& address) {
  const std::string shown = redactedAddress(address);
  PGconn* conn = PQconnectdb(address.c_str());
  if (conn == nullptr) throw DbError(shown, "cannot connect: out of memory");
  if (PQstatus(conn) != CONNECTION_OK) {
    std::string message = trimmed(PQerrorMessage(conn));
    PQfinish(conn);
    // libpq puts "connection to server on socket ... failed: " before the reason.
    if (const std::size_t reason = message.find("failed: "); reason != std::string::npos) {
      message = message.substr(reason + 8);
    }
    throw DbError(shown, "cannot connect to the server: " + message, "08001");
  }
  PQsetNoticeProcessor(conn, ignoreNotice, nullptr);
  const int version = PQserverVersion(conn);
  if (version < 150000) {
    PQfinish(conn);
    throw DbError(shown, "the server runs PostgreSQL " + std::to_string(version / 10000) +
                             "; Tactile needs PostgreSQL 15 or newer");
  }
  auto backend = std::make_unique<PgConnection>(conn, shown);
  backend->exec("SET client_min_messages = warning");
  return Connection(std::move(backend));
}

std::string serverVersion(Connection& connection) {
  if (connection.engine() != Engine::Postgres) return {};
  const int v = PQserverVersion(static_cast<PgConnection&>(connection.backend()).handle());
  return std::to_string(v / 10000) + "." + std::to_string(v % 10000);
}

}  // namespace tactile::storage::db
