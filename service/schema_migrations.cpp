#include "schema_migrations.hpp"

#include <algorithm>

#include "job_store.hpp"

namespace fosls::service {

int migrate_schema(SqlConnection& connection, const std::vector<SchemaMigration>& steps,
                   const SchemaHooks& hooks, const std::string& where) {
  const int latest = steps.empty() ? 0 : steps.back().version;
  SqlTransaction tx(connection);
  if (hooks.lock) hooks.lock(connection);
  // The same text is valid in both dialects.
  connection.exec(
      "CREATE TABLE IF NOT EXISTS schema_migrations ("
      "version INTEGER PRIMARY KEY, description TEXT NOT NULL, applied_at BIGINT NOT NULL)");
  int found = static_cast<int>(
      connection.query("SELECT coalesce(max(version), 0) AS version FROM schema_migrations")[0]
          .int64("version"));
  if (hooks.legacy_version) found = std::max(found, hooks.legacy_version(connection));
  if (found > latest) {
    throw StoreError(where + " has schema version " + std::to_string(found) +
                     ", newer than this program understands (" + std::to_string(latest) +
                     "); run the newer program, or a copy of the database from before it");
  }
  for (const SchemaMigration& step : steps) {
    if (step.version <= found) continue;
    connection.exec(step.sql);
    connection.query(
        "INSERT INTO schema_migrations (version, description, applied_at) "
        "VALUES (?1, ?2, {now_ms})",
        {static_cast<std::int64_t>(step.version), step.description});
  }
  if (hooks.after_steps) hooks.after_steps(connection, latest);
  tx.commit();
  return found;
}

}  // namespace fosls::service
