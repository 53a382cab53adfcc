// Tests of the study recorder. Expected values are the inputs themselves
// compared bit for bit (std::bit_cast), counts derived from what the test
// appended, and the SQLite file checked with SQLite's own integrity_check.
#include "rackopt/record/evaluation_store.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <bit>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <thread>

#include "support/sql_text.hpp"

namespace rackopt::record {
namespace {

namespace fs = std::filesystem;
using test_support::sql_text;

class StoreTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string tmpl = (fs::temp_directory_path() / "rackopt_record_XXXXXX").string();
    ASSERT_NE(mkdtemp(tmpl.data()), nullptr);
    dir_ = tmpl;
    db_ = (fs::path(dir_) / "out" / "evaluations.sqlite").string();
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string dir_, db_;
  const std::vector<std::string> vars_ = {"module_m", "face_width_m"};
};

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::bit_cast<std::uint64_t>(a[i]) != std::bit_cast<std::uint64_t>(b[i])) return false;
  }
  return true;
}

bool same_record(const RecordedEvaluation& a, const RecordedEvaluation& b) {
  if (a.metrics.size() != b.metrics.size()) return false;
  for (std::size_t i = 0; i < a.metrics.size(); ++i) {
    if (a.metrics[i].first != b.metrics[i].first ||
        std::bit_cast<std::uint64_t>(a.metrics[i].second) != std::bit_cast<std::uint64_t>(b.metrics[i].second)) {
      return false;
    }
  }
  return a.phase == b.phase && same_bits(a.x, b.x) && same_bits(a.objectives, b.objectives) &&
         same_bits(a.inequality, b.inequality) && same_bits(a.equality, b.equality) && a.ok == b.ok &&
         a.message == b.message && a.gradient_probe == b.gradient_probe && a.seconds == b.seconds &&
         a.warnings == b.warnings;
}

std::string thrown_message(auto&& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "<nothing thrown>";
}

RecordedEvaluation tricky_evaluation() {
  RecordedEvaluation e;
  e.phase = "pareto point 3";
  e.x = {0.1 + 0.2, std::numeric_limits<double>::denorm_min()};  // 0.30000000000000004, 4.9e-324
  e.objectives = {-0.0, DBL_MAX, std::numeric_limits<double>::infinity()};
  e.inequality = {-1e-310, std::bit_cast<double>(std::uint64_t{0x7ff8000000000abcull})};  // NaN with payload
  e.equality = {};
  e.metrics = {{"mass_kg", 1.5}, {"stiffness_N_per_m", -0.0}, {"life_s", 3.1536e8}};
  e.ok = false;
  e.message = "pointed tooth: s_a = -1e-4 m, \"quoted\", comma, newline\nand ü";
  e.gradient_probe = true;
  e.seconds = 0.125;
  // Every character the warnings cell escapes or ends on, an empty warning,
  // text that looks like an escape, and a trailing backslash.
  e.warnings = {"pinion undercut: z = 12 < z_min = 17.1", "", "two\nlines", "a \\n is not a line break",
                "back\\slash\\", "\n", "ü, \"quoted\""};
  return e;
}

TEST_F(StoreTest, EveryFieldRoundTripsBitExact) {
  const RecordedEvaluation in = tricky_evaluation();
  {
    auto store = EvaluationStore::open(db_, "fp", vars_, false);
    EXPECT_EQ(store.append(in), 1);
    const auto before_close = store.all();  // read back from the open (uncommitted) transaction
    ASSERT_EQ(before_close.size(), 1u);
    EXPECT_TRUE(same_record(before_close[0], in));
  }
  auto store = EvaluationStore::open(db_, "fp", vars_, true);
  const auto rows = store.all();
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].id, 1);
  EXPECT_TRUE(same_record(rows[0], in));
  EXPECT_EQ(store.variable_names(), vars_);
  EXPECT_EQ(store.metric_names(), (std::vector<std::string>{"mass_kg", "stiffness_N_per_m", "life_s"}));
}

TEST_F(StoreTest, WarningsRoundTripThroughFindAndAllAndMayBeEmpty) {
  RecordedEvaluation with = tricky_evaluation(), without = tricky_evaluation(), one_empty = tricky_evaluation();
  with.x = {1.0, 2.0};
  without.x = {3.0, 4.0};
  without.warnings.clear();
  one_empty.x = {5.0, 6.0};
  one_empty.warnings = {""};  // one empty warning is not "no warning"
  {
    auto store = EvaluationStore::open(db_, "fp", vars_, false);
    store.append(with);
    store.append(without);
    store.append(one_empty);
  }
  auto store = EvaluationStore::open(db_, "fp", vars_, true);
  EXPECT_EQ(store.find(with.x)->warnings, with.warnings);
  EXPECT_TRUE(store.find(without.x)->warnings.empty());
  EXPECT_EQ(store.find(one_empty.x)->warnings, std::vector<std::string>{""});
  const auto rows = store.all();
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].warnings.size(), 7u);
  EXPECT_EQ(rows[0].warnings, with.warnings);
}

// A file written before warnings were recorded: the version-1 tables exactly
// as that version created them, one row, its meta.
void write_schema_1_file(const std::string& path, const std::vector<double>& x) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  const char* ddl = R"sql(
CREATE TABLE meta(key TEXT PRIMARY KEY NOT NULL, value TEXT NOT NULL) WITHOUT ROWID;
CREATE TABLE variables(position INTEGER PRIMARY KEY, name TEXT NOT NULL);
CREATE TABLE metric_names(metric_id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE);
CREATE TABLE evaluations(
  id INTEGER PRIMARY KEY, phase TEXT NOT NULL, x_hash INTEGER NOT NULL, x BLOB NOT NULL,
  objectives BLOB NOT NULL, inequality BLOB NOT NULL, equality BLOB NOT NULL,
  metric_ids BLOB NOT NULL, metric_values BLOB NOT NULL, ok INTEGER NOT NULL, message TEXT NOT NULL,
  gradient_probe INTEGER NOT NULL, seconds REAL NOT NULL);
CREATE INDEX evaluations_by_x ON evaluations(x_hash);
INSERT INTO meta VALUES('rackopt.schema', 'rackopt-evaluations 1'), ('rackopt.study_fingerprint', 'fp');
INSERT INTO variables VALUES(0, 'module_m'), (1, 'face_width_m');
)sql";
  ASSERT_EQ(sqlite3_exec(db, ddl, nullptr, nullptr, nullptr), SQLITE_OK) << sqlite3_errmsg(db);
  // x as the store encodes it (little-endian doubles) with its FNV-1a key.
  std::string bytes;
  for (double v : x)
    for (int b = 0; b < 8; ++b) bytes.push_back(static_cast<char>((std::bit_cast<std::uint64_t>(v) >> (8 * b)) & 0xffu));
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  sqlite3_stmt* s = nullptr;
  ASSERT_EQ(sqlite3_prepare_v2(db,
                               "INSERT INTO evaluations VALUES(1, 'start', ?1, ?2, x'', x'', x'', x'', x'', 1, "
                               "'', 0, 0.5)",
                               -1, &s, nullptr),
            SQLITE_OK);
  sqlite3_bind_int64(s, 1, std::bit_cast<std::int64_t>(h));
  sqlite3_bind_blob(s, 2, bytes.data(), static_cast<int>(bytes.size()), SQLITE_TRANSIENT);
  EXPECT_EQ(sqlite3_step(s), SQLITE_DONE);
  sqlite3_finalize(s);
  sqlite3_close(db);
}

TEST_F(StoreTest, SchemaOneFileIsUpgradedAndItsRowsHaveNoWarnings) {
  fs::create_directories(fs::path(db_).parent_path());
  const std::vector<double> old_x = {2e-3, 0.05};
  write_schema_1_file(db_, old_x);
  const std::string has_column = "SELECT count(*) FROM pragma_table_info('evaluations') WHERE name = 'warnings'";

  // A refused open (no --resume) leaves the old file exactly as it was.
  EXPECT_THROW(EvaluationStore::open(db_, "fp", vars_, false), OutputFolderConflict);
  EXPECT_EQ(sql_text(db_, has_column), "0");
  EXPECT_EQ(sql_text(db_, "SELECT value FROM meta WHERE key = 'rackopt.schema'"), "rackopt-evaluations 1");

  RecordedEvaluation fresh = tricky_evaluation();
  fresh.x = {3e-3, 0.06};
  {
    auto store = EvaluationStore::open(db_, "fp", vars_, true);
    ASSERT_EQ(store.size(), 1u);
    const auto old = store.find(old_x);
    ASSERT_TRUE(old.has_value());
    EXPECT_EQ(old->id, 1);
    EXPECT_EQ(old->phase, "start");
    EXPECT_EQ(old->seconds, 0.5);
    EXPECT_TRUE(old->warnings.empty());
    EXPECT_EQ(store.append(fresh), 2);
  }
  EXPECT_EQ(sql_text(db_, has_column), "1");
  EXPECT_EQ(sql_text(db_, "SELECT value FROM meta WHERE key = 'rackopt.schema'"), "rackopt-evaluations 4");
  // The old row got its real columns from its blob; the view has them.
  EXPECT_EQ(sql_text(db_, "SELECT module_m FROM evaluations WHERE id = 1"), "0.002");
  EXPECT_EQ(sql_text(db_, "SELECT face_width_m FROM evaluations WHERE id = 2"), "0.06");
  EXPECT_EQ(sql_text(db_, "PRAGMA integrity_check"), "ok");
  auto store = EvaluationStore::open(db_, "fp", vars_, true);
  const auto rows = store.all();
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_TRUE(rows[0].warnings.empty());
  EXPECT_TRUE(same_record(rows[1], fresh));
  // The old row has no checksum to check: kept and counted; the new one has.
  EXPECT_EQ(store.unchecked_rows(), 1u);
  EXPECT_EQ(store.damaged_rows_removed(), 0u);
}

// Sets one cell of one row with SQLite directly, as a failing disk or a hand
// edit would change it.
void set_cell(const std::string& path, const std::string& sql, const std::string& blob) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  sqlite3_stmt* s = nullptr;
  ASSERT_EQ(sqlite3_prepare_v2(db, sql.c_str(), -1, &s, nullptr), SQLITE_OK) << sqlite3_errmsg(db);
  sqlite3_bind_blob(s, 1, blob.data(), static_cast<int>(blob.size()), SQLITE_TRANSIENT);
  EXPECT_EQ(sqlite3_step(s), SQLITE_DONE) << sqlite3_errmsg(db);
  sqlite3_finalize(s);
  sqlite3_close(db);
}

TEST_F(StoreTest, ARowThatFailsItsChecksumIsNotReused) {
  std::vector<RecordedEvaluation> rows(3, tricky_evaluation());
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i].x = {1.0 + static_cast<double>(i), 2.0};
  {
    auto store = EvaluationStore::open(db_, "fp", vars_, false);
    for (const auto& r : rows) store.append(r);
  }
  // One bit of row 2's second objective (DBL_MAX) flipped.
  std::string objectives;
  for (double v : rows[1].objectives)
    for (int b = 0; b < 8; ++b) objectives.push_back(static_cast<char>((std::bit_cast<std::uint64_t>(v) >> (8 * b)) & 0xffu));
  objectives[8] = static_cast<char>(objectives[8] ^ 0x01);
  set_cell(db_, "UPDATE evaluation_records SET objectives = ?1 WHERE id = 2", objectives);
  // And row 3's message, changed by one byte as text.
  set_cell(db_, "UPDATE evaluation_records SET message = CAST(?1 AS TEXT) WHERE id = 3", "pointed tooth: s_a = -2e-4 m");
  {
    auto store = EvaluationStore::open(db_, "fp", vars_, true);
    EXPECT_EQ(store.damaged_rows_removed(), 2u);
    EXPECT_EQ(store.unchecked_rows(), 0u);
    EXPECT_EQ(store.size(), 1u);
    ASSERT_TRUE(store.find(rows[0].x).has_value());
    EXPECT_TRUE(same_record(*store.find(rows[0].x), rows[0]));
    EXPECT_FALSE(store.find(rows[1].x).has_value());  // evaluated again by the runner...
    EXPECT_FALSE(store.find(rows[2].x).has_value());
    store.append(rows[1]);  // ... and recorded anew
  }
  {
    auto store = EvaluationStore::open(db_, "fp", vars_, true);
    EXPECT_EQ(store.damaged_rows_removed(), 0u);
    EXPECT_EQ(store.size(), 2u);
    EXPECT_TRUE(same_record(*store.find(rows[1].x), rows[1]));
  }
  EXPECT_EQ(sql_text(db_, "PRAGMA integrity_check"), "ok");
}

TEST_F(StoreTest, UnknownSchemaVersionIsRefused) {
  fs::create_directories(fs::path(db_).parent_path());
  write_schema_1_file(db_, {1.0, 2.0});
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(db_.c_str(), &db), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(db, "UPDATE meta SET value = 'rackopt-evaluations 9' WHERE key = 'rackopt.schema'", nullptr,
                         nullptr, nullptr),
            SQLITE_OK);
  sqlite3_close(db);
  const std::string msg = thrown_message([&] { EvaluationStore::open(db_, "fp", vars_, true); });
  EXPECT_NE(msg.find("another rackopt version (rackopt-evaluations 9"), std::string::npos) << msg;
  EXPECT_EQ(sql_text(db_, "SELECT count(*) FROM pragma_table_info('evaluations') WHERE name = 'warnings'"), "0");
}

TEST(StoreColumnName, PlainSqlNamesOfVariablesAndMetrics) {
  EXPECT_EQ(column_name("pinion.pressure_angle"), "pinion_pressure_angle");
  EXPECT_EQ(column_name("wear_life_at_R(0.9)"), "wear_life_at_R_0_9");
  EXPECT_EQ(column_name("min_stiffness_ks(500)"), "min_stiffness_ks_500");
  EXPECT_EQ(column_name("contact_ratio"), "contact_ratio");
  EXPECT_EQ(column_name("..a..b.."), "a_b");
  EXPECT_EQ(column_name("3d"), "c_3d");
  EXPECT_EQ(column_name("\xc3\xa9t\xc3\xa9"), "t");
}

// Every variable and metric is a real column of the `evaluations` view, so
// that plain SQL filters evaluations; each column's unit and source name are
// in value_columns; the models and warnings are beside them.
TEST_F(StoreTest, VariablesAndMetricsAreRealColumnsSqlCanFilter) {
  const std::vector<std::string> vars = {"pinion.module", "rack.span", "ok"};
  StoreOptions options;
  options.units = {{"pinion.module", "m"}, {"rack.span", "m"}, {"contact_ratio", "-"}, {"wear_life_at_R(0.9)", "s"}};
  {
    auto store = EvaluationStore::open(db_, "fp", vars, false, options);
    for (int i = 0; i < 5; ++i) {
      RecordedEvaluation e;
      e.x = {0.01 + 0.001 * i, 1.5, -0.0};
      e.metrics = {{"contact_ratio", 1.3 + 0.05 * i}};
      if (i >= 3) e.metrics.emplace_back("wear_life_at_R(0.9)", 1e9 * i);  // a column that appears later
      e.ok = i != 2;
      e.models = {"geometry", "stiffness_curve"};
      e.warnings = {"undercut"};
      store.append(e);
    }
    const auto rows = store.all();
    EXPECT_EQ(rows[4].models, (std::vector<std::string>{"geometry", "stiffness_curve"}));
  }
  EXPECT_EQ(sql_text(db_, "SELECT count(*) FROM evaluations WHERE contact_ratio > 1.42"), "2");
  EXPECT_EQ(sql_text(db_, "SELECT group_concat(id) FROM evaluations WHERE wear_life_at_R_0_9 IS NULL"), "1,2,3");
  EXPECT_EQ(sql_text(db_, "SELECT pinion_module FROM evaluations WHERE id = 3"), "0.012");
  EXPECT_EQ(sql_text(db_, "SELECT typeof(rack_span) FROM evaluations LIMIT 1"), "real");
  // A variable named like one of the view's own columns gets another name.
  EXPECT_EQ(sql_text(db_, "SELECT name FROM value_columns WHERE source = 'ok'"), "ok_2");
  EXPECT_EQ(sql_text(db_, "SELECT count(*) FROM evaluations WHERE ok = 0"), "1");
  EXPECT_EQ(sql_text(db_, "SELECT unit FROM value_columns WHERE name = 'wear_life_at_R_0_9'"), "s");
  EXPECT_EQ(sql_text(db_, "SELECT kind || ' ' || source FROM value_columns WHERE name = 'pinion_module'"),
            "variable pinion.module");
  EXPECT_EQ(sql_text(db_, "SELECT models FROM evaluations WHERE id = 5"), "geometry,stiffness_curve");
  EXPECT_EQ(sql_text(db_, "SELECT count(*) FROM evaluations WHERE warnings LIKE '%undercut%'"), "5");
  // The blobs resume reads stay out of the view.
  EXPECT_EQ(sql_text(db_, "SELECT count(*) FROM pragma_table_info('evaluations') WHERE name IN ('x', 'metric_values')"),
            "0");
  // Resumed: the columns are those of the file, and new rows fill them.
  {
    auto store = EvaluationStore::open(db_, "fp", vars, true, options);
    RecordedEvaluation e;
    e.x = {0.02, 2.0, 1.0};
    e.metrics = {{"wear_life_at_R(0.9)", 7e9}, {"contact_ratio", 1.45}};
    store.append(e);
  }
  EXPECT_EQ(sql_text(db_, "SELECT count(*) FROM evaluations WHERE contact_ratio > 1.42"), "3");
  EXPECT_EQ(sql_text(db_, "SELECT wear_life_at_R_0_9 FROM evaluations WHERE id = 6"), "7000000000.0");
  EXPECT_EQ(sql_text(db_, "SELECT count(*) FROM value_columns"), "5");
  EXPECT_EQ(sql_text(db_, "PRAGMA integrity_check"), "ok");
}

// An empty store taken over by another study loses the value columns of
// the one before.
TEST_F(StoreTest, ReclaimedEmptyStoreHasOnlyTheNewStudysColumns) {
  { auto store = EvaluationStore::open(db_, "first", {"a.b", "c"}, false); }
  { auto store = EvaluationStore::open(db_, "second", {"d"}, false); }
  EXPECT_EQ(sql_text(db_, "SELECT group_concat(name) FROM value_columns"), "d");
  EXPECT_EQ(sql_text(db_, "SELECT count(*) FROM pragma_table_info('evaluation_records') WHERE name = 'a_b'"), "0");
}

TEST_F(StoreTest, FindIsExactOnBitsAndSeesUncommittedRows) {
  auto store = EvaluationStore::open(db_, "fp", vars_, false, {.commit_every = 1000000, .commit_interval_seconds = 1e9});
  RecordedEvaluation e;
  e.x = {0.1 + 0.2, 0.0};
  e.objectives = {1.0};
  EXPECT_EQ(store.append(e), 1);
  e.x = {0.3, -0.0};
  e.objectives = {2.0};
  EXPECT_EQ(store.append(e), 2);
  e.x = {0.1 + 0.2, 0.0};  // duplicate of row 1: find() must answer with the earliest
  e.objectives = {3.0};
  EXPECT_EQ(store.append(e), 3);
  EXPECT_EQ(store.committed_size(), 0u);  // nothing committed yet, find() must still see the rows

  const std::vector<double> a = {0.1 + 0.2, 0.0}, b = {0.3, -0.0}, c = {0.3, 0.0}, d = {0.30000000000000004, 0.0};
  ASSERT_TRUE(store.find(a).has_value());
  EXPECT_EQ(store.find(a)->id, 1);
  EXPECT_EQ(store.find(a)->objectives, std::vector<double>{1.0});
  EXPECT_EQ(store.find(b)->id, 2);
  EXPECT_FALSE(store.find(c).has_value());  // -0.0 and +0.0 are different keys
  EXPECT_EQ(store.find(d)->id, 1);          // the literal 0.30000000000000004 is the same double as 0.1+0.2
  const std::vector<double> miss = {0.3, 1e-300};
  EXPECT_FALSE(store.find(miss).has_value());
  const std::vector<double> wrong_size = {0.3};
  EXPECT_THROW(store.find(wrong_size), std::invalid_argument);
  RecordedEvaluation bad;
  bad.x = {1.0};
  EXPECT_THROW(store.append(bad), std::invalid_argument);
}

TEST_F(StoreTest, OtherStudyInTheFolderIsRefusedWithAdvice) {
  {
    auto store = EvaluationStore::open(db_, "study-A", vars_, false);
    store.append(tricky_evaluation());
  }
  const std::string msg = thrown_message([&] { EvaluationStore::open(db_, "study-B", vars_, true); });
  EXPECT_NE(msg.find("another study"), std::string::npos) << msg;
  EXPECT_NE(msg.find("--out"), std::string::npos) << msg;
  EXPECT_NE(msg.find("delete"), std::string::npos) << msg;
  // The refused open left the file as it was.
  auto store = EvaluationStore::open(db_, "study-A", vars_, true);
  EXPECT_EQ(store.size(), 1u);
}

// Fingerprints of another format cannot be compared: refused by name, the
// file untouched; a file from before formats were stored counts as "1".
TEST_F(StoreTest, AnotherFingerprintFormatIsRefusedByName) {
  StoreOptions v1;
  v1.fingerprint_format = "1";
  {
    auto store = EvaluationStore::open(db_, "fp", vars_, false, v1);
    store.append(tricky_evaluation());
  }
  EXPECT_EQ(sql_text(db_, "SELECT value FROM meta WHERE key = 'rackopt.fingerprint_format'"), "1");
  StoreOptions v2;
  v2.fingerprint_format = "2";
  const std::string msg = thrown_message([&] { EvaluationStore::open(db_, "fp", vars_, true, v2); });
  EXPECT_NE(msg.find("fingerprint of format 1, and this rackopt computes format 2"), std::string::npos) << msg;
  EXPECT_EQ(EvaluationStore::open(db_, "fp", vars_, true, v1).size(), 1u);

  const std::string old_db = (fs::path(db_).parent_path() / "old.sqlite").string();
  write_schema_1_file(old_db, {1.0, 2.0});
  EXPECT_THROW(EvaluationStore::open(old_db, "fp", vars_, true, v2), OutputFolderConflict);
  EXPECT_EQ(EvaluationStore::open(old_db, "fp", vars_, true, v1).size(), 1u);
}

TEST_F(StoreTest, ExistingResultsNeedResume) {
  {
    auto store = EvaluationStore::open(db_, "fp", vars_, false);
    store.append(tricky_evaluation());
    store.append(tricky_evaluation());
  }
  const std::string msg = thrown_message([&] { EvaluationStore::open(db_, "fp", vars_, false); });
  EXPECT_NE(msg.find("already holds 2 evaluations"), std::string::npos) << msg;
  EXPECT_NE(msg.find("--resume"), std::string::npos) << msg;
  EXPECT_EQ(EvaluationStore::open(db_, "fp", vars_, true).size(), 2u);
}

TEST_F(StoreTest, EmptyStoreIsReclaimedByAnyStudy) {
  EvaluationStore::open(db_, "study-A", vars_, false).close();
  const std::vector<std::string> other_vars = {"a", "b", "c"};
  auto store = EvaluationStore::open(db_, "study-B", other_vars, false);
  EXPECT_EQ(store.dimension(), 3u);
  EXPECT_EQ(store.size(), 0u);
}

TEST_F(StoreTest, FailedEvaluationsCounted) {
  {
    auto store = EvaluationStore::open(db_, "fp", vars_, false);
    for (int i = 0; i < 5; ++i) {
      RecordedEvaluation e;
      e.x = {double(i), 1.0};
      e.ok = i % 2 == 1;  // rows 1 and 3 ok, 0, 2, 4 failed
      if (!e.ok) e.message = "contact ratio below 1";
      store.append(e);
    }
    EXPECT_EQ(store.size(), 5u);
    EXPECT_EQ(store.failed_count(), 3u);
  }
  auto store = EvaluationStore::open(db_, "fp", vars_, true);
  EXPECT_EQ(store.size(), 5u);
  EXPECT_EQ(store.failed_count(), 3u);
}

TEST_F(StoreTest, CommitsByCountByTimeAndOnClose) {
  auto store = EvaluationStore::open(db_, "fp", vars_, false, {.commit_every = 4, .commit_interval_seconds = 1e9});
  RecordedEvaluation e;
  for (int i = 0; i < 10; ++i) {
    e.x = {double(i), 0.0};
    store.append(e);
  }
  EXPECT_EQ(store.committed_size(), 8u);  // two batches of 4; 2 pending
  store.flush();
  EXPECT_EQ(store.committed_size(), 10u);

  auto timed = EvaluationStore::open((fs::path(dir_) / "timed.sqlite").string(), "fp", vars_, false,
                                     {.commit_every = 1000, .commit_interval_seconds = 0.05});
  e.x = {0.0, 0.0};
  timed.append(e);  // soon after open: stays pending
  std::this_thread::sleep_for(std::chrono::milliseconds(80));
  e.x = {1.0, 0.0};
  timed.append(e);  // 80 ms after the last commit > 50 ms: commits both
  EXPECT_EQ(timed.committed_size(), 2u);

  {
    auto lazy = EvaluationStore::open((fs::path(dir_) / "lazy.sqlite").string(), "fp", vars_, false,
                                      {.commit_every = 1000, .commit_interval_seconds = 1e9});
    for (int i = 0; i < 7; ++i) {
      e.x = {double(i), 0.0};
      lazy.append(e);
    }
    EXPECT_EQ(lazy.committed_size(), 0u);
  }  // destructor commits
  EXPECT_EQ(EvaluationStore::open((fs::path(dir_) / "lazy.sqlite").string(), "fp", vars_, true).size(), 7u);
}

TEST_F(StoreTest, MetaRoundTripAndReservedKeys) {
  {
    auto store = EvaluationStore::open(db_, "fp", vars_, false);
    EXPECT_FALSE(store.meta("status").has_value());
    store.set_meta("status", "running");
    store.set_meta("status", "finished");
    store.set_meta("summary", "{\"best\": [1, 2]}");
    EXPECT_THROW(store.set_meta("rackopt.study_fingerprint", "x"), std::invalid_argument);
    store.append(tricky_evaluation());
  }
  auto store = EvaluationStore::open(db_, "fp", vars_, true);
  EXPECT_EQ(store.meta("status"), "finished");
  EXPECT_EQ(store.meta("summary"), "{\"best\": [1, 2]}");
}

TEST_F(StoreTest, SecondWriterAndForeignFilesRefused) {
  auto store = EvaluationStore::open(db_, "fp", vars_, false);
  const std::string msg = thrown_message([&] { EvaluationStore::open(db_, "fp", vars_, true); });
  EXPECT_NE(msg.find("in use"), std::string::npos) << msg;

  const std::string junk = (fs::path(dir_) / "junk.sqlite").string();
  std::ofstream(junk) << "this is a CSV, not a database\n1,2,3\n";
  const std::string junk_msg = thrown_message([&] { EvaluationStore::open(junk, "fp", vars_, true); });
  EXPECT_NE(junk_msg.find("not a readable rackopt evaluation database"), std::string::npos) << junk_msg;
}

// Minimal RFC 4180 reader written for this test (quotes, doubled quotes, embedded newlines).
std::vector<std::vector<std::string>> parse_csv(const std::string& text) {
  std::vector<std::vector<std::string>> rows(1);
  std::string field;
  bool quoted = false, at_start = true;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        field += c;
      }
    } else if (c == '"' && at_start) {
      quoted = true;
    } else if (c == ',') {
      rows.back().push_back(field);
      field.clear();
      at_start = true;
      continue;
    } else if (c == '\n') {
      rows.back().push_back(field);
      field.clear();
      rows.emplace_back();
      at_start = true;
      continue;
    } else {
      field += c;
    }
    at_start = false;
  }
  if (rows.back().empty()) rows.pop_back();
  return rows;
}

TEST_F(StoreTest, CsvExportReadsBackExactly) {
  auto store = EvaluationStore::open(db_, "fp", vars_, false);
  RecordedEvaluation ok;
  ok.phase = "start 0";
  ok.x = {2e-3, 0.1 + 0.2};
  ok.objectives = {12.5, 1.0 / 3.0};
  ok.inequality = {-0.25};
  ok.metrics = {{"life_s", 1e9}, {"mass_kg", 4.75}};
  ok.seconds = 0.001;
  store.append(ok);
  store.append(tricky_evaluation());  // failed, 3 objectives, 2 inequality, other metrics

  const std::string csv = (fs::path(dir_) / "tables" / "evaluations.csv").string();
  write_evaluations_csv(store, vars_, {"mass_kg", "life_s", "stiffness_N_per_m"}, csv);
  std::stringstream ss;
  ss << std::ifstream(csv).rdbuf();
  const auto rows = parse_csv(ss.str());
  ASSERT_EQ(rows.size(), 3u);
  // This store was opened without units: names as they are.
  const std::vector<std::string> header = {"id", "phase", "ok", "message", "gradient_probe", "seconds_s",
                                           "module_m", "face_width_m", "scaled_objective_0", "scaled_objective_1",
                                           "scaled_objective_2", "scaled_inequality_0", "scaled_inequality_1",
                                           "mass_kg", "life_s", "stiffness_N_per_m"};
  EXPECT_EQ(rows[0], header);
  for (const auto& r : rows) ASSERT_EQ(r.size(), header.size());
  auto num = [](const std::string& s) { return std::strtod(s.c_str(), nullptr); };
  EXPECT_EQ(rows[1][0], "1");
  EXPECT_EQ(rows[1][1], "start 0");
  EXPECT_EQ(rows[1][2], "1");
  EXPECT_EQ(std::bit_cast<std::uint64_t>(num(rows[1][7])), std::bit_cast<std::uint64_t>(0.1 + 0.2));
  EXPECT_EQ(num(rows[1][9]), 1.0 / 3.0);
  EXPECT_EQ(rows[1][10], "");  // the first row has only 2 objectives
  EXPECT_EQ(num(rows[1][13]), 4.75);
  EXPECT_EQ(num(rows[1][14]), 1e9);
  EXPECT_EQ(rows[1][15], "");  // the first row has no stiffness metric
  EXPECT_EQ(rows[2][2], "0");
  EXPECT_EQ(rows[2][3], tricky_evaluation().message);
  EXPECT_EQ(rows[2][4], "1");
  EXPECT_EQ(num(rows[2][7]), std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(rows[2][10], "inf");
  EXPECT_EQ(num(rows[2][13]), 1.5);
  EXPECT_EQ(num(rows[2][14]), 3.1536e8);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(num(rows[2][15])), std::bit_cast<std::uint64_t>(-0.0));
  // No temporary file left behind.
  EXPECT_EQ(std::distance(fs::directory_iterator(fs::path(csv).parent_path()), fs::directory_iterator()), 1);
  EXPECT_THROW(write_evaluations_csv(store, {"only_one"}, {}, csv), std::invalid_argument);
}

// --- kill -9 durability and resume ------------------------------------------

// A deterministic "study driver": design i and its (cheap) evaluation.
std::vector<double> design(int i) { return {1e-3 * (1 + i % 50), 0.01 * std::sin(0.37 * i)}; }

RecordedEvaluation evaluate(int i) {
  RecordedEvaluation e;
  e.phase = "sweep";
  e.x = design(i);
  e.ok = i % 17 != 5;
  if (e.ok) {
    e.objectives = {e.x[0] * e.x[0] + e.x[1]};
    e.inequality = {e.x[1] - 0.005};
    e.metrics = {{"mass_kg", 7850 * e.x[0]}, {"index", double(i)}};
  } else {
    e.message = "design " + std::to_string(i) + " fails";
  }
  e.seconds = 1e-6 * i;
  return e;
}

constexpr int kDesigns = 3000;

// Runs the driver against the store; returns how many designs were computed
// (the rest were answered by the record). `after_append` sees the store after each append.
int run_driver(EvaluationStore& store, const std::function<void(const EvaluationStore&)>& after_append = {}) {
  int computed = 0;
  for (int i = 0; i < kDesigns; ++i) {
    if (store.find(design(i))) continue;
    ++computed;
    store.append(evaluate(i));
    if (after_append) after_append(store);
  }
  return computed;
}

TEST_F(StoreTest, KillNineLosesOnlyTheUncommittedTailAndResumeCompletes) {
  // design(i) repeats x0 every 50 and sin never repeats exactly: all 3000 designs distinct.
  {
    std::set<std::vector<double>> distinct;
    for (int i = 0; i < kDesigns; ++i) distinct.insert(design(i));
    ASSERT_EQ(distinct.size(), std::size_t(kDesigns));
  }
  fs::create_directories(fs::path(db_).parent_path());
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // Child: no gtest here; report committed counts through the pipe, slowly
    // enough that the parent kills it mid-run.
    close(fds[0]);
    int code = 0;
    try {
      auto store = EvaluationStore::open(db_, "fp", vars_, false, {.commit_every = 25, .commit_interval_seconds = 1e9});
      std::uint64_t reported = 0;
      run_driver(store, [&](const EvaluationStore& s) {
        if (s.committed_size() != reported) {
          reported = s.committed_size();
          if (write(fds[1], &reported, sizeof reported) != sizeof reported) _exit(3);
        }
        usleep(300);
      });
      for (;;) pause();  // never finish on our own: the parent's SIGKILL ends us
    } catch (...) {
      code = 2;
    }
    _exit(code);
  }
  close(fds[1]);
  std::uint64_t last_committed = 0, report = 0;
  while (last_committed < 100) {
    const ssize_t n = read(fds[0], &report, sizeof report);
    if (n != sizeof report) break;
    last_committed = report;
  }
  kill(child, SIGKILL);
  int status = 0;
  waitpid(child, &status, 0);
  close(fds[0]);
  ASSERT_GE(last_committed, 100u) << "child ended early, status " << status;
  ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);

  // The file after the kill: SQLite's own check, and contiguous ids from 1.
  {
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open_v2(db_.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr), SQLITE_OK);
    sqlite3_stmt* s = nullptr;
    ASSERT_EQ(sqlite3_prepare_v2(db, "PRAGMA integrity_check", -1, &s, nullptr), SQLITE_OK);
    ASSERT_EQ(sqlite3_step(s), SQLITE_ROW);
    EXPECT_STREQ(reinterpret_cast<const char*>(sqlite3_column_text(s, 0)), "ok");
    sqlite3_finalize(s);
    ASSERT_EQ(sqlite3_prepare_v2(db, "SELECT count(*), min(id), max(id) FROM evaluations", -1, &s, nullptr),
              SQLITE_OK);
    ASSERT_EQ(sqlite3_step(s), SQLITE_ROW);
    const auto count = sqlite3_column_int64(s, 0);
    EXPECT_GE(count, std::int64_t(last_committed));
    EXPECT_EQ(sqlite3_column_int64(s, 1), 1);
    EXPECT_EQ(sqlite3_column_int64(s, 2), count);
    sqlite3_finalize(s);
    sqlite3_close(db);
  }

  auto store = EvaluationStore::open(db_, "fp", vars_, true);
  const std::size_t recovered = store.size();
  EXPECT_GE(recovered, last_committed);
  EXPECT_LT(recovered, std::size_t(kDesigns));
  {
    const auto rows = store.all();
    for (std::size_t i = 0; i < rows.size(); ++i) {
      EXPECT_EQ(rows[i].id, std::int64_t(i + 1));
      EXPECT_TRUE(same_record(rows[i], evaluate(int(i)))) << "row " << i + 1 << " incomplete or wrong";
    }
  }
  // Resume: only the designs not recorded are computed; the end state equals an uninterrupted run.
  const int computed = run_driver(store);
  EXPECT_EQ(computed, kDesigns - int(recovered));
  EXPECT_EQ(store.size(), std::size_t(kDesigns));
  auto fresh = EvaluationStore::open((fs::path(dir_) / "fresh.sqlite").string(), "fp", vars_, false);
  EXPECT_EQ(run_driver(fresh), kDesigns);
  const auto resumed_rows = store.all(), fresh_rows = fresh.all();
  ASSERT_EQ(resumed_rows.size(), fresh_rows.size());
  for (std::size_t i = 0; i < fresh_rows.size(); ++i) {
    EXPECT_EQ(resumed_rows[i].id, fresh_rows[i].id);
    EXPECT_TRUE(same_record(resumed_rows[i], fresh_rows[i])) << "row " << i + 1;
  }
  EXPECT_EQ(store.failed_count(), fresh.failed_count());
}

}  // namespace
}  // namespace rackopt::record

namespace rackopt::record {
namespace {

// A name with a double quote stays one identifier: SQLite makes exactly one
// column of it, named as given, and the text after the quote is no SQL.
TEST(SqlIdentifier, AQuoteInsideANameCannotEndTheIdentifier) {
  EXPECT_EQ(sql_identifier("plain"), "\"plain\"");
  EXPECT_EQ(sql_identifier("a\"b"), "\"a\"\"b\"");
  EXPECT_THROW(sql_identifier(std::string("a\0b", 3)), std::invalid_argument);

  const std::string hostile = "x\" REAL); DROP TABLE t; CREATE TABLE owned(\"y";
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(":memory:", &db), SQLITE_OK);
  const std::string ddl = "CREATE TABLE t(" + sql_identifier(hostile) + " REAL)";
  ASSERT_EQ(sqlite3_exec(db, ddl.c_str(), nullptr, nullptr, nullptr), SQLITE_OK) << sqlite3_errmsg(db);
  std::vector<std::string> columns, tables;
  sqlite3_stmt* s = nullptr;
  ASSERT_EQ(sqlite3_prepare_v2(db, "SELECT name FROM pragma_table_info('t')", -1, &s, nullptr), SQLITE_OK);
  while (sqlite3_step(s) == SQLITE_ROW) columns.emplace_back(reinterpret_cast<const char*>(sqlite3_column_text(s, 0)));
  sqlite3_finalize(s);
  ASSERT_EQ(sqlite3_prepare_v2(db, "SELECT name FROM sqlite_master WHERE type = 'table'", -1, &s, nullptr), SQLITE_OK);
  while (sqlite3_step(s) == SQLITE_ROW) tables.emplace_back(reinterpret_cast<const char*>(sqlite3_column_text(s, 0)));
  sqlite3_finalize(s);
  sqlite3_close(db);
  EXPECT_EQ(columns, std::vector<std::string>{hostile});
  EXPECT_EQ(tables, std::vector<std::string>{"t"});
}

}  // namespace
}  // namespace rackopt::record
