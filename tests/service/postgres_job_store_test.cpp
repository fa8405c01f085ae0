// What only the PostgreSQL store has (the shared contract is job_store_contract_test.cpp):
// several processes creating the schema at once, a schema newer than the program, and
// connections that survive a restart of the server.

#include "postgres_job_store.hpp"

#include <gtest/gtest.h>
#include <libpq-fe.h>

#include <atomic>
#include <thread>
#include <vector>

#include "store_test_support.hpp"

namespace fosls::service {
namespace {

using testing::claim_as;
using testing::kUnlimited;
using testing::make_job;
using testing::shared_postgres;

void sql(const std::string& url, const std::string& text) {
  PGconn* c = PQconnectdb(url.c_str());
  PGresult* r = PQexec(c, text.c_str());
  EXPECT_TRUE(PQresultStatus(r) == PGRES_COMMAND_OK || PQresultStatus(r) == PGRES_TUPLES_OK)
      << text << ": " << PQerrorMessage(c);
  PQclear(r);
  PQfinish(c);
}

TEST(PostgresJobStore, SeveralProcessesCreateTheSchemaAtOnce) {
  const std::string url = shared_postgres().create_database("schema_race");
  std::atomic<int> failures{0};
  std::vector<std::thread> starting;
  for (int i = 0; i < 6; ++i) {
    starting.emplace_back([&] {
      try {
        PostgresJobStore store(url);
        store.ping();
      } catch (const StoreError&) {
        ++failures;
      }
    });
  }
  for (auto& t : starting) t.join();
  EXPECT_EQ(failures.load(), 0);
  PostgresJobStore store(url);
  EXPECT_EQ(store.submit(make_job("1"), kUnlimited).kind, SubmitOutcome::Kind::kCreated);
}

TEST(PostgresJobStore, SchemaFromANewerProgramIsRefused) {
  const std::string url = shared_postgres().create_database("schema_newer");
  { PostgresJobStore store(url); }
  sql(url, "INSERT INTO schema_migrations VALUES (99, 'from the future', 0)");
  try {
    PostgresJobStore store(url);
    FAIL() << "opened a database of schema version 99";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find("schema version 99"), std::string::npos) << e.what();
  }
}

// The server restarts under a running store: calls fail while it is away, then work again on
// fresh connections, and a job claimed before the restart completes after it.
TEST(PostgresJobStore, ConnectionsAreReplacedAfterTheServerRestarts) {
  testing::PostgresCluster server;  // its own, since it is stopped
  PostgresJobStore store(server.create_database("restart"));
  const auto id = store.submit(make_job("1"), kUnlimited).job->id;
  const Lease lease = store.claim_next(claim_as())->lease;
  server.stop();
  EXPECT_THROW(store.ping(), StoreError);
  server.start();
  // The pooled connections are broken; each is replaced after the call that finds it so.
  int failed = 0;
  for (int i = 0; i < 20; ++i) {
    try {
      store.ping();
    } catch (const StoreError&) {
      ++failed;
    }
  }
  EXPECT_LE(failed, 8);  // at most one failure per pooled connection
  EXPECT_NO_THROW(store.ping());
  EXPECT_TRUE(store.complete_succeeded(lease, "{}", "<VTKFile/>"));
  EXPECT_EQ(store.find(id)->state, JobState::kSucceeded);
}

}  // namespace
}  // namespace fosls::service
