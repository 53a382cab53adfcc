// The first cell of a query on a closed SQLite file (an evaluation store),
// read with SQLite directly, as a user's sqlite3 shell would see it.
#pragma once

#include <sqlite3.h>

#include <string>

namespace rackopt::test_support {

// The cell as text; "<no row>" when the file cannot be opened or the query
// fails or returns nothing, "<null>" for NULL.
inline std::string sql_text(const std::string& path, const std::string& query) {
  sqlite3* db = nullptr;
  std::string out = "<no row>";
  if (sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr) == SQLITE_OK) {
    sqlite3_stmt* s = nullptr;
    if (sqlite3_prepare_v2(db, query.c_str(), -1, &s, nullptr) == SQLITE_OK && sqlite3_step(s) == SQLITE_ROW) {
      const auto* t = reinterpret_cast<const char*>(sqlite3_column_text(s, 0));
      out = t ? t : "<null>";
    }
    sqlite3_finalize(s);
  }
  sqlite3_close(db);
  return out;
}

}  // namespace rackopt::test_support
