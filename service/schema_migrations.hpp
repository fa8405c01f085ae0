#pragma once
// Schema versions of a job store, created and migrated by the programs themselves: a list of
// numbered steps per store, applied in order in one transaction and recorded in the table
// schema_migrations. A later change (a new column) is one more step at the end of the steps
// both stores share (SqlJobStore::schema_steps).

#include <functional>
#include <string>
#include <vector>

#include "sql_connection.hpp"

namespace fosls::service {

/// One step from version - 1 to version.
struct SchemaMigration {
  int version = 0;
  std::string description;
  std::string sql;  ///< dialect SQL, several statements allowed
};

/// What differs between stores around the common steps.
struct SchemaHooks {
  /// Serialises concurrent migrators (PostgreSQL: an advisory lock; SQLite's BEGIN IMMEDIATE
  /// already does). Runs inside the transaction.
  std::function<void(SqlConnection&)> lock;
  /// A version recorded outside schema_migrations by older programs (SQLite's user_version);
  /// 0 when none.
  std::function<int(SqlConnection&)> legacy_version;
  /// Runs inside the transaction after the steps, with the version reached.
  std::function<void(SqlConnection&, int)> after_steps;
};

/// Brings the database to the last version of `steps` (ordered, starting at 1). Throws
/// StoreError naming `where` if the database is newer than this program. Returns the version
/// found before migrating (0 for a new database).
int migrate_schema(SqlConnection& connection, const std::vector<SchemaMigration>& steps,
                   const SchemaHooks& hooks, const std::string& where);

}  // namespace fosls::service
