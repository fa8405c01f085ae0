// The --store URL and the options both programs share: what is accepted, what is refused with
// a message, and that passwords stay out of the logs.

#include "store_url.hpp"

#include <gtest/gtest.h>

#include "temp_dir.hpp"
#include "worker_options.hpp"

namespace fosls::service {
namespace {

TEST(StoreUrl, SqliteAndPostgresql) {
  const StoreLocation file = parse_store_url("sqlite:data/fosls.db");
  EXPECT_EQ(file.kind, StoreLocation::Kind::kSqlite);
  EXPECT_EQ(file.target, "data/fosls.db");
  EXPECT_EQ(parse_store_url("sqlite:///var/lib/fosls.db").target, "/var/lib/fosls.db");
  const StoreLocation pg = parse_store_url("postgresql://fosls:secret@db:5432/fosls");
  EXPECT_EQ(pg.kind, StoreLocation::Kind::kPostgres);
  EXPECT_EQ(pg.target, "postgresql://fosls:secret@db:5432/fosls");
  EXPECT_EQ(parse_store_url("postgres://db/fosls").kind, StoreLocation::Kind::kPostgres);
}

TEST(StoreUrl, AnythingElseIsRefusedSayingWhatIsAccepted) {
  for (const char* bad : {"", "data/fosls.db", "sqlite:", "mysql://db/x", "http://x"}) {
    try {
      parse_store_url(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("sqlite:"), std::string::npos) << e.what();
    }
  }
}

TEST(StoreUrl, PasswordsAreRedactedForLogs) {
  EXPECT_EQ(redacted(parse_store_url("postgresql://fosls:secret@db:5432/fosls")),
            "postgresql://fosls:***@db:5432/fosls");
  EXPECT_EQ(redacted(parse_store_url("postgresql://fosls@db/fosls")),
            "postgresql://fosls@db/fosls");
  EXPECT_EQ(redacted(parse_store_url("postgresql://db/fosls")), "postgresql://db/fosls");
  EXPECT_EQ(redacted(parse_store_url("sqlite:x.db")), "sqlite:x.db");
}

TEST(StoreUrl, ASqliteFileBelongsToOneProgram) {
  testing::TempDir dir;
  const StoreLocation location = parse_store_url("sqlite:" + dir.file("sub/jobs.db"));
  OpenedStore first = open_store(location, "fosls-serve", 3);  // creates the folder
  ASSERT_TRUE(first.store);
  try {
    open_store(location, "fosls-worker", 3);
    ADD_FAILURE() << "a second program opened the same SQLite file";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("postgresql"), std::string::npos) << e.what();
  }
}

TEST(StoreUrl, UnreachablePostgresqlIsAStoreErrorWithTheReason) {
  // Port 1 on loopback: nothing listens there.
  try {
    open_store(parse_store_url("postgresql://fosls@127.0.0.1:1/fosls?connect_timeout=2"),
               "fosls-worker", 3);
    ADD_FAILURE() << "connected to nothing";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot connect to PostgreSQL"), std::string::npos)
        << e.what();
  }
}

TEST(WorkerOptions, ALeaseMustOutlastThreeHeartbeats) {
  WorkerOptions o;
  EXPECT_EQ(o.problem(), "");
  o.lease_seconds = 2;
  o.heartbeat_seconds = 1;
  EXPECT_NE(o.problem().find("--heartbeat-seconds 1 is too long for --lease-seconds 2"),
            std::string::npos)
      << o.problem();
  o.heartbeat_seconds = 0.5;
  EXPECT_EQ(o.problem(), "");
}

}  // namespace
}  // namespace fosls::service
