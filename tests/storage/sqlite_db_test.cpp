#include <gtest/gtest.h>

#include "storage/sqlite/sqlite_connection.h"

namespace tactile::storage::db {
namespace {

Connection memoryDb() {
  Connection c = Connection::open(":memory:", true);
  c.exec("CREATE TABLE t(v INTEGER)");
  return c;
}

TEST(SqliteDb, TransactionRollsBackUnlessCommitted) {
  Connection c = memoryDb();
  {
    Transaction t(c);
    c.exec("INSERT INTO t VALUES(1)");
  }
  EXPECT_EQ(c.queryInt("SELECT count(*) FROM t"), 0);
  {
    Transaction t(c);
    c.exec("INSERT INTO t VALUES(1)");
    t.commit();
    EXPECT_FALSE(t.active());
  }
  EXPECT_EQ(c.queryInt("SELECT count(*) FROM t"), 1);
}

TEST(SqliteDb, MovedTransactionKeepsOneOwner) {
  Connection c = memoryDb();
  {
    Transaction first(c);
    c.exec("INSERT INTO t VALUES(7)");
    Transaction second(std::move(first));
    EXPECT_FALSE(first.active());  // NOLINT(bugprone-use-after-move): checking the moved-from state
    EXPECT_TRUE(second.active());
    second.commit();
  }
  EXPECT_EQ(c.queryInt("SELECT sum(v) FROM t"), 7);
}

TEST(SqliteDb, StatementIsReusedByRebinding) {
  Connection c = memoryDb();
  Statement insert(c, "INSERT INTO t VALUES(?)");
  for (int i = 1; i <= 4; ++i) {
    insert.bind(1, i);
    insert.step();
  }
  EXPECT_EQ(c.queryInt("SELECT sum(v) FROM t"), 10);
}

TEST(SqliteDb, BadSqlNamesTheStatement) {
  Connection c = memoryDb();
  try {
    Statement s(c, "SELEC nonsense");
    FAIL() << "prepare should fail";
  } catch (const DbError& e) {
    EXPECT_NE(std::string(e.what()).find("SELEC nonsense"), std::string::npos) << e.what();
  }
}

TEST(SqliteDb, ConstraintFailureIsAnError) {
  Connection c = memoryDb();
  c.exec("CREATE TABLE u(k INTEGER PRIMARY KEY)");
  c.exec("INSERT INTO u VALUES(1)");
  Statement s(c, "INSERT INTO u VALUES(1)");
  EXPECT_THROW(s.step(), DbError);
}

TEST(SqliteDb, OpenWithoutCreateFailsForMissingFile) {
  EXPECT_THROW(Connection::open("/nonexistent-dir/x.db", false), DbError);
}

}  // namespace
}  // namespace tactile::storage::db
