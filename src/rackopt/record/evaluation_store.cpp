#include "rackopt/record/evaluation_store.hpp"

#include <sqlite3.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string_view>
#include <unordered_map>

#include "rackopt/core/fnv1a.hpp"
#include "rackopt/record/record_checksum.hpp"

namespace rackopt::record {
namespace {

// Bumped whenever the tables change. Version 2 added the warnings; version
// 3 renamed the table to evaluation_records, added the models and one real
// column per variable and metric, and the `evaluations` view over them.
// Version 4 added each row's checksum (record_checksum).
// Files of versions 1, 2 and 3 are upgraded in place when opened
// (load_or_create).
constexpr const char* kSchemaVersion = "rackopt-evaluations 4";
constexpr const char* kSchemaVersion3 = "rackopt-evaluations 3";
constexpr const char* kSchemaVersion2 = "rackopt-evaluations 2";
constexpr const char* kSchemaVersion1 = "rackopt-evaluations 1";
constexpr const char* kSchemaKey = "rackopt.schema";
constexpr const char* kFingerprintKey = "rackopt.study_fingerprint";
constexpr const char* kFingerprintFormatKey = "rackopt.fingerprint_format";
constexpr const char* kFirstFingerprintFormat = "1";  // files written before the format was stored

constexpr const char* kCreateSchema = R"sql(
CREATE TABLE IF NOT EXISTS meta(key TEXT PRIMARY KEY NOT NULL, value TEXT NOT NULL) WITHOUT ROWID;
CREATE TABLE IF NOT EXISTS variables(position INTEGER PRIMARY KEY, name TEXT NOT NULL);
CREATE TABLE IF NOT EXISTS metric_names(metric_id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE);
CREATE TABLE IF NOT EXISTS value_columns(
  name TEXT PRIMARY KEY NOT NULL COLLATE NOCASE, source TEXT NOT NULL, kind TEXT NOT NULL, unit TEXT NOT NULL,
  position INTEGER NOT NULL UNIQUE);
CREATE TABLE IF NOT EXISTS evaluation_records(
  id INTEGER PRIMARY KEY,
  phase TEXT NOT NULL,
  x_hash INTEGER NOT NULL,
  x BLOB NOT NULL,
  objectives BLOB NOT NULL,
  inequality BLOB NOT NULL,
  equality BLOB NOT NULL,
  metric_ids BLOB NOT NULL,
  metric_values BLOB NOT NULL,
  ok INTEGER NOT NULL,
  message TEXT NOT NULL,
  gradient_probe INTEGER NOT NULL,
  seconds REAL NOT NULL,
  warnings TEXT NOT NULL DEFAULT '',
  models TEXT NOT NULL DEFAULT '',
  record_checksum INTEGER);
CREATE INDEX IF NOT EXISTS evaluations_by_x ON evaluation_records(x_hash);
)sql";

constexpr const char* kSelectColumns =
    "SELECT id, phase, x, objectives, inequality, equality, metric_ids, metric_values, ok, message, "
    "gradient_probe, seconds, warnings, models FROM evaluation_records ";

// What a row's checksum covers, in its order, with x_hash first and the
// checksum itself last (verify_checksums).
constexpr const char* kChecksumColumns =
    "SELECT id, x_hash, phase, x, objectives, inequality, equality, metric_ids, metric_values, ok, message, "
    "gradient_probe, seconds, warnings, models, record_checksum FROM evaluation_records ";

// The view's own columns: a variable or metric column takes another name.
constexpr const char* kViewColumns[] = {"id", "phase", "ok", "message", "gradient_probe", "seconds", "models",
                                         "warnings"};
// ... nor may it take a name of the record table's own columns.
constexpr const char* kRecordColumns[] = {"x_hash", "x", "objectives", "inequality", "equality", "metric_ids",
                                           "metric_values", "record_checksum"};

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Names and lists of models as one TEXT cell: "geometry,stiffness_curve".
std::string join_models(const std::vector<std::string>& models) {
  std::string out;
  for (const auto& m : models) {
    if (m.find(',') != std::string::npos) throw std::invalid_argument("EvaluationStore: a model name with a comma: " + m);
    out += (out.empty() ? "" : ",") + m;
  }
  return out;
}

std::vector<std::string> split_models(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t comma = text.find(',', start);
    const std::size_t end = comma == std::string::npos ? text.size() : comma;
    out.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return out;
}


// --- little-endian byte encoding of numbers (bit exact, portable files) -----
template <class T>
void put_le(std::string& out, T value) {
  static_assert(sizeof(T) == 8);
  const auto bits = std::bit_cast<std::uint64_t>(value);
  for (int b = 0; b < 8; ++b) out.push_back(static_cast<char>((bits >> (8 * b)) & 0xffu));
}

template <class T>
T get_le(const unsigned char* p) {
  std::uint64_t bits = 0;
  for (int b = 0; b < 8; ++b) bits |= static_cast<std::uint64_t>(p[b]) << (8 * b);
  return std::bit_cast<T>(bits);
}

std::string encode_doubles(std::span<const double> v) {
  std::string out;
  out.reserve(8 * v.size());
  for (double d : v) put_le(out, d);
  return out;
}

// FNV-1a over the encoded bytes: the index key of x (equality is then
// checked on the full blob, so collisions only cost a comparison).
std::int64_t hash_bytes(const std::string& bytes) { return std::bit_cast<std::int64_t>(fnv1a64(bytes)); }

// The bytes of one row that resume reads, exactly as they are stored.
// Warnings as one TEXT cell: each warning followed by a line break; inside a
// warning a backslash is written as two backslashes and a line break as
// backslash-n. So any list (empty strings and line breaks included) reads
// back unchanged, and the usual case stays one readable line per warning in
// the sqlite3 shell.
std::string encode_warnings(const std::vector<std::string>& warnings) {
  std::string out;
  for (const auto& w : warnings) {
    for (char c : w) {
      if (c == '\\') {
        out += "\\\\";
      } else if (c == '\n') {
        out += "\\n";
      } else {
        out.push_back(c);
      }
    }
    out.push_back('\n');
  }
  return out;
}

// The inverse of encode_warnings; false on text it cannot have written.
bool decode_warnings(const std::string& text, std::vector<std::string>& out) {
  out.clear();
  std::string w;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') {
      out.push_back(std::move(w));
      w.clear();
    } else if (c == '\\') {
      if (i + 1 >= text.size()) return false;
      const char n = text[++i];
      if (n == '\\') {
        w.push_back('\\');
      } else if (n == 'n') {
        w.push_back('\n');
      } else {
        return false;
      }
    } else {
      w.push_back(c);
    }
  }
  return w.empty();  // every warning ends with '\n'
}

struct StmtDeleter {
  void operator()(sqlite3_stmt* s) const { sqlite3_finalize(s); }
};
using Stmt = std::unique_ptr<sqlite3_stmt, StmtDeleter>;

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

std::string column_name(const std::string& name) {
  std::string out;
  for (char c : name) {
    const bool word = std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    if (word && static_cast<unsigned char>(c) < 128) {
      out.push_back(c);
    } else if (!out.empty() && out.back() != '_') {
      out.push_back('_');
    }
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  std::size_t lead = 0;
  while (lead < out.size() && out[lead] == '_') ++lead;
  out.erase(0, lead);
  if (out.empty() || std::isdigit(static_cast<unsigned char>(out[0]))) out = "c_" + out;
  return out;
}

std::string sql_identifier(const std::string& name) {
  if (name.find('\0') != std::string::npos) throw std::invalid_argument("an SQL name cannot hold a NUL byte");
  std::string out = "\"";
  for (char c : name) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

struct EvaluationStore::Impl {
  std::string path;
  StoreOptions options;
  sqlite3* db = nullptr;
  std::vector<std::string> variables;
  std::vector<std::string> metric_by_id;  // metric_id - 1 -> name
  std::unordered_map<std::string, std::int64_t> metric_ids;
  std::size_t count = 0, failed = 0, committed = 0;
  std::size_t pending = 0;  // appends in the open transaction
  bool in_transaction = false;
  std::chrono::steady_clock::time_point last_commit = std::chrono::steady_clock::now();
  Stmt insert_eval, insert_metric_name, find_by_x, begin, commit;
  // The real columns: the variables' in order, then the metrics' by id.
  std::vector<std::string> variable_columns;
  std::vector<std::string> metric_columns;  // metric_id - 1 -> column
  std::vector<std::string> taken;           // lower-case names in use

  static constexpr int kRecordParams = 15;  // insert_eval's parameters before the real columns
  std::size_t damaged = 0;    // rows removed at open: they failed their checksum
  std::size_t unchecked = 0;  // rows recorded before checksums (version 3 or older)

  ~Impl() {
    try {
      finish();
    } catch (...) {
      // A destructor cannot report; close() is the way to see this error.
    }
  }

  [[noreturn]] void fail(const std::string& what, int rc) const {
    std::string detail = db ? sqlite3_errmsg(db) : sqlite3_errstr(rc);
    if (rc == SQLITE_BUSY || rc == SQLITE_LOCKED) {
      // A user decision like the other folder conflicts (exit 2), not a failed run.
      throw OutputFolderConflict("'" + path + "' is in use by another rackopt run (or another program " +
                               "holds it open): " + what + " failed. Wait for that run to end or " +
                               "choose another --out folder.");
    }
    if (rc == SQLITE_NOTADB || rc == SQLITE_CORRUPT) {
      throw std::runtime_error("'" + path + "' is not a readable rackopt evaluation database (" +
                               detail + "); delete it or choose another --out folder.");
    }
    throw std::runtime_error("evaluation store '" + path + "': " + what + " failed: " + detail);
  }

  void exec(const char* sql, const char* what) {
    const int rc = sqlite3_exec(db, sql, nullptr, nullptr, nullptr);
    if (rc != SQLITE_OK) fail(what, rc);
  }

  Stmt prepare(const char* sql) const {
    sqlite3_stmt* s = nullptr;
    const int rc = sqlite3_prepare_v3(db, sql, -1, SQLITE_PREPARE_PERSISTENT, &s, nullptr);
    if (rc != SQLITE_OK) fail(std::string("preparing \"") + sql + "\"", rc);
    return Stmt(s);
  }

  // Steps a statement that returns no row, then resets it.
  void run(sqlite3_stmt* s, const char* what) const {
    const int rc = sqlite3_step(s);
    sqlite3_reset(s);
    sqlite3_clear_bindings(s);
    if (rc != SQLITE_DONE) fail(what, rc);
  }

  void bind_text(sqlite3_stmt* s, int i, const std::string& v) const {
    sqlite3_bind_text(s, i, v.data(), static_cast<int>(v.size()), SQLITE_TRANSIENT);
  }
  void bind_blob(sqlite3_stmt* s, int i, const std::string& v) const {
    // A zero-length blob, not NULL, for empty vectors (columns are NOT NULL).
    sqlite3_bind_blob(s, i, v.empty() ? "" : v.data(), static_cast<int>(v.size()), SQLITE_TRANSIENT);
  }

  std::optional<std::string> read_meta(const std::string& key) const {
    Stmt s = prepare("SELECT value FROM meta WHERE key = ?1");
    bind_text(s.get(), 1, key);
    const int rc = sqlite3_step(s.get());
    if (rc == SQLITE_ROW) {
      const auto* text = reinterpret_cast<const char*>(sqlite3_column_text(s.get(), 0));
      return std::string(text ? text : "", static_cast<std::size_t>(sqlite3_column_bytes(s.get(), 0)));
    }
    if (rc != SQLITE_DONE) fail("reading meta key '" + key + "'", rc);
    return std::nullopt;
  }

  void write_meta(const std::string& key, const std::string& value) {
    Stmt s = prepare("INSERT INTO meta(key, value) VALUES(?1, ?2) "
                     "ON CONFLICT(key) DO UPDATE SET value = excluded.value");
    bind_text(s.get(), 1, key);
    bind_text(s.get(), 2, value);
    run(s.get(), "writing meta");
  }

  std::int64_t scalar(const char* sql) const {
    Stmt s = prepare(sql);
    const int rc = sqlite3_step(s.get());
    if (rc != SQLITE_ROW) fail(sql, rc);
    return sqlite3_column_int64(s.get(), 0);
  }

  void begin_if_needed() {
    if (in_transaction) return;
    run(begin.get(), "BEGIN");
    in_transaction = true;
  }

  void commit_now() {
    if (in_transaction) {
      run(commit.get(), "COMMIT");
      in_transaction = false;
    }
    pending = 0;
    committed = count;
    last_commit = std::chrono::steady_clock::now();
  }

  void finish() {
    if (!db) return;
    std::exception_ptr error;
    try {
      commit_now();
    } catch (...) {
      error = std::current_exception();
    }
    insert_eval.reset();
    insert_metric_name.reset();
    find_by_x.reset();
    begin.reset();
    commit.reset();
    sqlite3_close_v2(db);
    db = nullptr;
    if (error) std::rethrow_exception(error);
  }

  void load_or_create(const std::string& study_fingerprint, const std::string& fingerprint_format,
                      const std::vector<std::string>& variable_names,
                      bool resume);

  std::int64_t metric_id(const std::string& name) {
    if (auto it = metric_ids.find(name); it != metric_ids.end()) return it->second;
    const auto id = static_cast<std::int64_t>(metric_by_id.size()) + 1;
    sqlite3_bind_int64(insert_metric_name.get(), 1, id);
    bind_text(insert_metric_name.get(), 2, name);
    run(insert_metric_name.get(), "recording a metric name");
    metric_by_id.push_back(name);
    metric_ids.emplace(name, id);
    metric_columns.push_back(add_column(name, "metric"));
    rebuild_view();
    prepare_insert();
    return id;
  }

  std::string unused_column(const std::string& source) {
    const std::string base = column_name(source);
    std::string name = base;
    for (int k = 2; std::find(taken.begin(), taken.end(), lower(name)) != taken.end(); ++k)
      name = base + "_" + std::to_string(k);
    taken.push_back(lower(name));
    return name;
  }

  // A real column for a variable or metric: added to the records, described
  // in value_columns. Returns its name.
  std::string add_column(const std::string& source, const char* kind) {
    const std::string name = unused_column(source);
    exec(("ALTER TABLE evaluation_records ADD COLUMN " + sql_identifier(name) + " REAL").c_str(), "adding a value column");
    Stmt s = prepare("INSERT INTO value_columns(name, source, kind, unit, position) "
                     "VALUES(?1, ?2, ?3, ?4, (SELECT count(*) FROM value_columns))");
    bind_text(s.get(), 1, name);
    bind_text(s.get(), 2, source);
    bind_text(s.get(), 3, kind);
    const auto unit = options.units.find(source);
    bind_text(s.get(), 4, unit == options.units.end() ? std::string() : unit->second);
    run(s.get(), "describing a value column");
    return name;
  }

  // The view users query: the records' readable columns and the real ones,
  // without the blobs resume reads.
  void rebuild_view() {
    std::string sql = "DROP VIEW IF EXISTS evaluations; CREATE VIEW evaluations AS SELECT id, phase, ok, message, "
                      "gradient_probe, seconds";
    for (const auto& c : variable_columns) sql += ", " + sql_identifier(c);
    for (const auto& c : metric_columns) sql += ", " + sql_identifier(c);
    sql += ", models, warnings FROM evaluation_records";
    exec(sql.c_str(), "creating the evaluations view");
  }

  void prepare_insert() {
    std::string sql = "INSERT INTO evaluation_records(phase, x_hash, x, objectives, inequality, equality, metric_ids, "
                      "metric_values, ok, message, gradient_probe, seconds, warnings, models, record_checksum";
    std::string values = "VALUES(?1,?2,?3,?4,?5,?6,?7,?8,?9,?10,?11,?12,?13,?14,?15";
    int k = kRecordParams;
    for (const auto* columns : {&variable_columns, &metric_columns}) {
      for (const auto& c : *columns) {
        sql += ", " + sql_identifier(c);
        values += ",?" + std::to_string(++k);
      }
    }
    insert_eval = prepare((sql + ") " + values + ")").c_str());
  }

  // Binds the real columns of `e` to parameters offset + 1 on, in the
  // columns' order (the variables', then the metrics' by id); a metric the
  // row lacks stays NULL.
  void bind_real_columns(sqlite3_stmt* s, int offset, const RecordedEvaluation& e) const {
    int k = offset;
    for (double v : e.x) sqlite3_bind_double(s, ++k, v);
    for (const auto& [name, value] : e.metrics)
      sqlite3_bind_double(s, offset + static_cast<int>(e.x.size() + metric_ids.at(name)), value);
  }

  // Rows recorded before version 3 get their real columns from their blobs.
  void fill_value_columns() {
    std::string sql = "UPDATE evaluation_records SET ";
    int k = 0;
    for (const auto* columns : {&variable_columns, &metric_columns})
      for (const auto& c : *columns) {
        sql += (k ? ", " : "") + sql_identifier(c);
        sql += " = ?" + std::to_string(++k);
      }
    if (k == 0) return;
    sql += " WHERE id = ?" + std::to_string(k + 1);
    Stmt update = prepare(sql.c_str());
    Stmt rows = prepare((std::string(kSelectColumns) + "ORDER BY id").c_str());
    int rc;
    while ((rc = sqlite3_step(rows.get())) == SQLITE_ROW) {
      const RecordedEvaluation e = read_row(rows.get());
      bind_real_columns(update.get(), 0, e);
      sqlite3_bind_int64(update.get(), k + 1, e.id);
      run(update.get(), "filling the value columns of an older row");
    }
    if (rc != SQLITE_DONE) fail("reading older rows", rc);
  }

  // Every row's checksum against its bytes: a row that fails it (a flipped
  // bit on disk, a hand edit) is deleted, so its design is evaluated again
  // rather than reused; rows from before checksums are counted, not checked.
  void verify_checksums() {
    Stmt rows = prepare((std::string(kChecksumColumns) + "ORDER BY id").c_str());
    auto bytes = [&rows](int col) {
      const auto* p = static_cast<const char*>(sqlite3_column_blob(rows.get(), col));
      return std::string_view(p ? p : "", static_cast<std::size_t>(sqlite3_column_bytes(rows.get(), col)));
    };
    std::vector<std::int64_t> bad;
    int rc;
    while ((rc = sqlite3_step(rows.get())) == SQLITE_ROW) {
      if (sqlite3_column_type(rows.get(), 15) == SQLITE_NULL) {
        ++unchecked;
        continue;
      }
      RowBytes r;
      r.x_hash = sqlite3_column_int64(rows.get(), 1);
      r.phase = bytes(2);
      r.x = bytes(3);
      r.objectives = bytes(4);
      r.inequality = bytes(5);
      r.equality = bytes(6);
      r.metric_ids = bytes(7);
      r.metric_values = bytes(8);
      r.ok = sqlite3_column_int64(rows.get(), 9);
      r.message = bytes(10);
      r.gradient_probe = sqlite3_column_int64(rows.get(), 11);
      r.seconds = sqlite3_column_double(rows.get(), 12);
      r.warnings = bytes(13);
      r.models = bytes(14);
      // A stored value of another type (a hand edit) reads as a number that cannot match.
      const bool typed = sqlite3_column_type(rows.get(), 1) == SQLITE_INTEGER &&
                         sqlite3_column_type(rows.get(), 9) == SQLITE_INTEGER &&
                         sqlite3_column_type(rows.get(), 11) == SQLITE_INTEGER &&
                         sqlite3_column_type(rows.get(), 12) == SQLITE_FLOAT &&
                         sqlite3_column_type(rows.get(), 15) == SQLITE_INTEGER;
      if (!typed || row_checksum(r) != sqlite3_column_int64(rows.get(), 15)) bad.push_back(sqlite3_column_int64(rows.get(), 0));
    }
    if (rc != SQLITE_DONE) fail("checking the rows' checksums", rc);
    rows.reset();
    Stmt remove = prepare("DELETE FROM evaluation_records WHERE id = ?1");
    for (const std::int64_t id : bad) {
      sqlite3_bind_int64(remove.get(), 1, id);
      run(remove.get(), "removing a row that failed its checksum");
    }
    damaged = bad.size();
    count -= bad.size();
  }

  RecordedEvaluation read_row(sqlite3_stmt* s) const {
    auto blob_doubles = [&](int col) {
      const int bytes = sqlite3_column_bytes(s, col);
      const auto* p = static_cast<const unsigned char*>(sqlite3_column_blob(s, col));
      if (bytes % 8 != 0) fail("reading a row (a number blob has " + std::to_string(bytes) + " bytes)", SQLITE_CORRUPT);
      std::vector<double> out(static_cast<std::size_t>(bytes / 8));
      for (std::size_t i = 0; i < out.size(); ++i) out[i] = get_le<double>(p + 8 * i);
      return out;
    };
    auto text = [&](int col) {
      const auto* t = reinterpret_cast<const char*>(sqlite3_column_text(s, col));
      return std::string(t ? t : "", static_cast<std::size_t>(sqlite3_column_bytes(s, col)));
    };
    RecordedEvaluation e;
    e.id = sqlite3_column_int64(s, 0);
    e.phase = text(1);
    e.x = blob_doubles(2);
    e.objectives = blob_doubles(3);
    e.inequality = blob_doubles(4);
    e.equality = blob_doubles(5);
    {
      const int id_bytes = sqlite3_column_bytes(s, 6);
      const auto* ids = static_cast<const unsigned char*>(sqlite3_column_blob(s, 6));
      const std::vector<double> values = blob_doubles(7);
      if (id_bytes != 8 * static_cast<int>(values.size())) fail("reading a row (metric ids and values differ in count)", SQLITE_CORRUPT);
      for (std::size_t i = 0; i < values.size(); ++i) {
        const auto id = get_le<std::int64_t>(ids + 8 * i);
        if (id < 1 || id > static_cast<std::int64_t>(metric_by_id.size())) fail("reading a row (unknown metric id)", SQLITE_CORRUPT);
        e.metrics.emplace_back(metric_by_id[static_cast<std::size_t>(id - 1)], values[i]);
      }
    }
    e.ok = sqlite3_column_int(s, 8) != 0;
    e.message = text(9);
    e.gradient_probe = sqlite3_column_int(s, 10) != 0;
    e.seconds = sqlite3_column_double(s, 11);
    if (!decode_warnings(text(12), e.warnings)) fail("reading a row (malformed warnings)", SQLITE_CORRUPT);
    e.models = split_models(text(13));
    return e;
  }

  void require_open(const char* who) const {
    if (!db) throw std::logic_error(std::string(who) + " on a closed evaluation store");
  }

  void check_dimension(std::size_t n, const char* who) const {
    require_open(who);
    if (n != variables.size()) {
      throw std::invalid_argument(std::string(who) + ": x has " + std::to_string(n) +
                                  " values but the study in '" + path + "' has " +
                                  std::to_string(variables.size()) + " variables");
    }
  }
};

EvaluationStore::EvaluationStore(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
EvaluationStore::EvaluationStore(EvaluationStore&&) noexcept = default;
EvaluationStore& EvaluationStore::operator=(EvaluationStore&&) noexcept = default;
EvaluationStore::~EvaluationStore() = default;

EvaluationStore EvaluationStore::open(const std::string& path, const std::string& study_fingerprint,
                                      const std::vector<std::string>& variable_names, bool resume,
                                      StoreOptions options) {
  if (options.commit_every == 0) throw std::invalid_argument("EvaluationStore: commit_every must be at least 1");
  if (!(options.commit_interval_seconds >= 0)) {
    throw std::invalid_argument("EvaluationStore: commit_interval_seconds must be >= 0");
  }
  auto impl = std::make_unique<Impl>();
  impl->path = path;
  impl->options = options;

  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(parent, ec);
    if (ec) throw std::runtime_error("cannot create folder '" + parent.string() + "': " + ec.message());
  }
  const int rc = sqlite3_open_v2(path.c_str(), &impl->db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr);
  if (rc != SQLITE_OK) impl->fail("opening", rc);
  sqlite3_extended_result_codes(impl->db, 0);

  // Exclusive locking before WAL: the lock taken by the first write below is
  // kept until close (one writer per output folder) and no shared-memory
  // index is needed. WAL + synchronous=FULL: a commit appends to the log and
  // fsyncs it, and a crash mid-commit leaves the previous state intact.
  impl->exec("PRAGMA locking_mode = EXCLUSIVE", "setting exclusive locking");
  {
    Stmt s = impl->prepare("PRAGMA journal_mode = WAL");
    const int step = sqlite3_step(s.get());
    if (step != SQLITE_ROW) impl->fail("switching to WAL mode", step);
    const std::string mode = reinterpret_cast<const char*>(sqlite3_column_text(s.get(), 0));
    if (mode != "wal") {
      throw std::runtime_error("evaluation store '" + path + "': the file system refused WAL mode (got '" +
                               mode + "'); put --out on a local disk");
    }
  }
  impl->exec("PRAGMA synchronous = FULL", "setting synchronous mode");

  impl->exec("BEGIN IMMEDIATE", "locking the store");
  impl->in_transaction = true;
  try {
    impl->load_or_create(study_fingerprint, options.fingerprint_format, variable_names, resume);
  } catch (...) {
    // Leave the file as it was (a refused open must not claim it).
    sqlite3_exec(impl->db, "ROLLBACK", nullptr, nullptr, nullptr);
    impl->in_transaction = false;
    throw;
  }
  impl->commit_now();
  return EvaluationStore(std::move(impl));
}

void EvaluationStore::Impl::load_or_create(const std::string& study_fingerprint, const std::string& fingerprint_format,
                                           const std::vector<std::string>& variable_names, bool resume) {
  // Before version 3 the records were the table `evaluations`, a name the
  // view now has.
  if (scalar("SELECT count(*) FROM sqlite_master WHERE type = 'table' AND name = 'evaluations'") > 0)
    exec("ALTER TABLE evaluations RENAME TO evaluation_records", "renaming the records table");
  exec(kCreateSchema, "creating the tables");
  const auto schema = read_meta(kSchemaKey);
  if (schema && *schema != kSchemaVersion && *schema != kSchemaVersion3 && *schema != kSchemaVersion2 &&
      *schema != kSchemaVersion1) {
    throw std::runtime_error("'" + path + "' was written by another rackopt version (" + *schema +
                             ", this one reads " + kSchemaVersion +
                             "); delete it or choose another --out folder.");
  }
  // Version 1 had no warnings column: add it (rows recorded before read as
  // having no warning). Inside the open transaction, so a refused open below
  // rolls the upgrade back with everything else.
  if (scalar("SELECT count(*) FROM pragma_table_info('evaluation_records') WHERE name = 'warnings'") == 0) {
    exec("ALTER TABLE evaluation_records ADD COLUMN warnings TEXT NOT NULL DEFAULT ''", "adding the warnings column");
  }
  // Version 2 had no models column.
  if (scalar("SELECT count(*) FROM pragma_table_info('evaluation_records') WHERE name = 'models'") == 0) {
    exec("ALTER TABLE evaluation_records ADD COLUMN models TEXT NOT NULL DEFAULT ''", "adding the models column");
  }
  // Version 3 had no checksums: its rows keep NULL and are reused unchecked.
  if (scalar("SELECT count(*) FROM pragma_table_info('evaluation_records') WHERE name = 'record_checksum'") == 0) {
    exec("ALTER TABLE evaluation_records ADD COLUMN record_checksum INTEGER", "adding the checksum column");
  }
  count = static_cast<std::size_t>(scalar("SELECT count(*) FROM evaluation_records"));
  if (count > 0) {
    const std::string stored_format = read_meta(kFingerprintFormatKey).value_or(kFirstFingerprintFormat);
    if (stored_format != fingerprint_format) {
      throw OutputFolderConflict("'" + path + "' holds " + std::to_string(count) +
                                 " evaluations identified by a study fingerprint of format " + stored_format +
                                 ", and this rackopt computes format " + fingerprint_format +
                                 ": it cannot tell whether they belong to this study. Choose another --out "
                                 "folder, or delete '" + path + "' to start this study afresh.");
    }
    const auto stored = read_meta(kFingerprintKey).value_or("");
    if (stored != study_fingerprint) {
      throw OutputFolderConflict("'" + path + "' holds " + std::to_string(count) +
                               " evaluations of another study (fingerprint " + stored + ", this study " +
                               study_fingerprint +
                               "): the study or problem definition changed since they were recorded. "
                               "Choose another --out folder, or delete '" + path +
                               "' to start this study afresh.");
    }
    if (!resume) {
      throw OutputFolderConflict("'" + path + "' already holds " + std::to_string(count) +
                               " evaluations of this study. Pass --resume to continue it (recorded "
                               "evaluations are reused, not recomputed), or choose another --out folder.");
    }
    Stmt s = prepare("SELECT name FROM variables ORDER BY position");
    int step;
    while ((step = sqlite3_step(s.get())) == SQLITE_ROW) {
      variables.emplace_back(reinterpret_cast<const char*>(sqlite3_column_text(s.get(), 0)));
    }
    if (step != SQLITE_DONE) fail("reading variable names", step);
    if (variables != variable_names) {
      throw OutputFolderConflict("'" + path + "' records other design variables than this study (same "
                               "fingerprint but different names or order); choose another --out folder.");
    }
    verify_checksums();
    failed = static_cast<std::size_t>(scalar("SELECT count(*) FROM evaluation_records WHERE ok = 0"));
    if (schema.value_or("") != kSchemaVersion) write_meta(kSchemaKey, kSchemaVersion);  // upgraded above
  } else {
    // Nothing recorded: the file is (re)claimed by this study, without the
    // value columns of the one before.
    exec("DROP VIEW IF EXISTS evaluations; DROP TABLE evaluation_records; DELETE FROM variables; "
         "DELETE FROM metric_names; DELETE FROM value_columns;",
         "resetting an empty store");
    exec(kCreateSchema, "creating the tables");
    write_meta(kSchemaKey, kSchemaVersion);
    write_meta(kFingerprintKey, study_fingerprint);
    write_meta(kFingerprintFormatKey, fingerprint_format);
    Stmt s = prepare("INSERT INTO variables(position, name) VALUES(?1, ?2)");
    for (std::size_t i = 0; i < variable_names.size(); ++i) {
      sqlite3_bind_int64(s.get(), 1, static_cast<std::int64_t>(i));
      bind_text(s.get(), 2, variable_names[i]);
      run(s.get(), "recording variable names");
    }
    variables = variable_names;
  }
  {
    Stmt s = prepare("SELECT metric_id, name FROM metric_names ORDER BY metric_id");
    int step;
    while ((step = sqlite3_step(s.get())) == SQLITE_ROW) {
      const std::string name(reinterpret_cast<const char*>(sqlite3_column_text(s.get(), 1)));
      if (sqlite3_column_int64(s.get(), 0) != static_cast<std::int64_t>(metric_by_id.size()) + 1) {
        fail("reading metric names (ids not contiguous)", SQLITE_CORRUPT);
      }
      metric_by_id.push_back(name);
      metric_ids.emplace(name, static_cast<std::int64_t>(metric_by_id.size()));
    }
    if (step != SQLITE_DONE) fail("reading metric names", step);
  }
  // The real columns: as recorded, or made now for a new file or one of an
  // older version (whose rows then get their values from their blobs).
  for (const char* c : kViewColumns) taken.push_back(c);
  for (const char* c : kRecordColumns) taken.push_back(c);
  {
    Stmt s = prepare("SELECT name, kind FROM value_columns ORDER BY position");
    int step;
    while ((step = sqlite3_step(s.get())) == SQLITE_ROW) {
      const std::string name(reinterpret_cast<const char*>(sqlite3_column_text(s.get(), 0)));
      const std::string kind(reinterpret_cast<const char*>(sqlite3_column_text(s.get(), 1)));
      (kind == "variable" ? variable_columns : metric_columns).push_back(name);
      taken.push_back(lower(name));
    }
    if (step != SQLITE_DONE) fail("reading the value columns", step);
  }
  if ((!variable_columns.empty() && variable_columns.size() != variables.size()) ||
      metric_columns.size() > metric_by_id.size())
    fail("reading the value columns (they do not match the variables and metrics)", SQLITE_CORRUPT);
  const bool older_rows = count > 0 && variable_columns.empty() && !variables.empty();
  if (variable_columns.empty())
    for (const auto& v : variables) variable_columns.push_back(add_column(v, "variable"));
  for (std::size_t i = metric_columns.size(); i < metric_by_id.size(); ++i)
    metric_columns.push_back(add_column(metric_by_id[i], "metric"));
  if (older_rows) fill_value_columns();
  rebuild_view();
  begin = prepare("BEGIN");
  commit = prepare("COMMIT");
  prepare_insert();
  insert_metric_name = prepare("INSERT INTO metric_names(metric_id, name) VALUES(?1, ?2)");
  find_by_x = prepare(
      (std::string(kSelectColumns) + "WHERE x_hash = ?1 AND x = ?2 ORDER BY id LIMIT 1").c_str());
}

std::optional<RecordedEvaluation> EvaluationStore::find(std::span<const double> x) const {
  impl_->check_dimension(x.size(), "EvaluationStore::find");
  const std::string key = encode_doubles(x);
  sqlite3_stmt* s = impl_->find_by_x.get();
  sqlite3_bind_int64(s, 1, hash_bytes(key));
  impl_->bind_blob(s, 2, key);
  std::optional<RecordedEvaluation> out;
  const int rc = sqlite3_step(s);
  if (rc == SQLITE_ROW) out = impl_->read_row(s);
  sqlite3_reset(s);
  sqlite3_clear_bindings(s);
  if (rc != SQLITE_ROW && rc != SQLITE_DONE) impl_->fail("looking up an evaluation", rc);
  return out;
}

std::int64_t EvaluationStore::append(const RecordedEvaluation& e) {
  Impl& m = *impl_;
  m.check_dimension(e.x.size(), "EvaluationStore::append");
  if (!std::isfinite(e.seconds)) {
    throw std::invalid_argument("EvaluationStore::append: evaluation time must be finite");
  }
  m.begin_if_needed();
  std::string ids, values;
  for (const auto& [name, value] : e.metrics) {
    put_le(ids, m.metric_id(name));
    put_le(values, value);
  }
  const std::string x = encode_doubles(e.x);
  const std::string objectives = encode_doubles(e.objectives), inequality = encode_doubles(e.inequality),
                    equality = encode_doubles(e.equality), warnings = encode_warnings(e.warnings),
                    models = join_models(e.models);
  RowBytes row;
  row.x_hash = hash_bytes(x);
  row.phase = e.phase;
  row.x = x;
  row.objectives = objectives;
  row.inequality = inequality;
  row.equality = equality;
  row.metric_ids = ids;
  row.metric_values = values;
  row.ok = e.ok ? 1 : 0;
  row.message = e.message;
  row.gradient_probe = e.gradient_probe ? 1 : 0;
  row.seconds = e.seconds;
  row.warnings = warnings;
  row.models = models;
  sqlite3_stmt* s = m.insert_eval.get();
  m.bind_text(s, 1, e.phase);
  sqlite3_bind_int64(s, 2, row.x_hash);
  m.bind_blob(s, 3, x);
  m.bind_blob(s, 4, objectives);
  m.bind_blob(s, 5, inequality);
  m.bind_blob(s, 6, equality);
  m.bind_blob(s, 7, ids);
  m.bind_blob(s, 8, values);
  sqlite3_bind_int(s, 9, static_cast<int>(row.ok));
  m.bind_text(s, 10, e.message);
  sqlite3_bind_int(s, 11, static_cast<int>(row.gradient_probe));
  sqlite3_bind_double(s, 12, e.seconds);
  m.bind_text(s, 13, warnings);
  m.bind_text(s, 14, models);
  sqlite3_bind_int64(s, 15, row_checksum(row));
  m.bind_real_columns(s, Impl::kRecordParams, e);
  m.run(s, "recording an evaluation");
  const std::int64_t id = sqlite3_last_insert_rowid(m.db);
  ++m.count;
  if (!e.ok) ++m.failed;
  ++m.pending;
  if (m.pending >= m.options.commit_every || seconds_since(m.last_commit) >= m.options.commit_interval_seconds) {
    m.commit_now();
  }
  return id;
}

void EvaluationStore::flush() {
  impl_->require_open("EvaluationStore::flush");
  impl_->commit_now();
}

void EvaluationStore::close() { impl_->finish(); }

void EvaluationStore::for_each(const std::function<void(const RecordedEvaluation&)>& visit) const {
  impl_->require_open("EvaluationStore::for_each");
  // A fresh statement per walk: visit() may call find() or even for_each().
  Stmt s = impl_->prepare((std::string(kSelectColumns) + "ORDER BY id").c_str());
  int rc;
  while ((rc = sqlite3_step(s.get())) == SQLITE_ROW) visit(impl_->read_row(s.get()));
  if (rc != SQLITE_DONE) impl_->fail("reading evaluations", rc);
}

std::vector<RecordedEvaluation> EvaluationStore::all() const {
  std::vector<RecordedEvaluation> out;
  out.reserve(impl_->count);
  for_each([&](const RecordedEvaluation& e) { out.push_back(e); });
  return out;
}

std::size_t EvaluationStore::size() const { return impl_->count; }
std::size_t EvaluationStore::failed_count() const { return impl_->failed; }
std::size_t EvaluationStore::committed_size() const { return impl_->committed; }
std::size_t EvaluationStore::damaged_rows_removed() const { return impl_->damaged; }
std::size_t EvaluationStore::unchecked_rows() const { return impl_->unchecked; }
std::int64_t EvaluationStore::last_id() const {
  impl_->require_open("EvaluationStore::last_id");
  return impl_->scalar("SELECT coalesce(max(id), 0) FROM evaluation_records");
}
std::size_t EvaluationStore::dimension() const { return impl_->variables.size(); }
const std::vector<std::string>& EvaluationStore::variable_names() const { return impl_->variables; }
std::vector<std::string> EvaluationStore::metric_names() const { return impl_->metric_by_id; }

std::map<std::string, std::string> EvaluationStore::column_units() const {
  impl_->require_open("EvaluationStore::column_units");
  std::map<std::string, std::string> out;
  Stmt s = impl_->prepare("SELECT source, unit FROM value_columns");
  int rc;
  while ((rc = sqlite3_step(s.get())) == SQLITE_ROW) {
    out.emplace(reinterpret_cast<const char*>(sqlite3_column_text(s.get(), 0)),
                reinterpret_cast<const char*>(sqlite3_column_text(s.get(), 1)));
  }
  if (rc != SQLITE_DONE) impl_->fail("reading the value columns' units", rc);
  return out;
}
const std::string& EvaluationStore::path() const { return impl_->path; }

void EvaluationStore::set_meta(const std::string& key, const std::string& value) {
  if (key.rfind("rackopt.", 0) == 0) {
    throw std::invalid_argument("EvaluationStore::set_meta: keys starting with 'rackopt.' are reserved ('" + key + "')");
  }
  impl_->require_open("EvaluationStore::set_meta");
  impl_->begin_if_needed();
  impl_->write_meta(key, value);
  impl_->commit_now();
}

std::optional<std::string> EvaluationStore::meta(const std::string& key) const {
  impl_->require_open("EvaluationStore::meta");
  return impl_->read_meta(key);
}

}  // namespace rackopt::record
