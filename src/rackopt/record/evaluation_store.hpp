// The study recorder: every evaluation of a study (optimizer, sweep, Pareto)
// appended to <out>/evaluations.sqlite as it happens, so that an interrupted
// study (Ctrl-C, kill -9, power cut) can resume without losing or repeating
// recorded work. See docs/recorder.md for the schema and the guarantees.
//
// Resume contract (carried out by the study runner): the runner re-runs the
// same deterministic driver; before evaluating a design x it calls find(x)
// and, on a hit, hands the recorded result to the solver instead of
// evaluating. Keys are the exact bit patterns of x, so a deterministic driver
// reproduces them and ends with the same result as an uninterrupted run.
//
// An EvaluationStore is one SQLite connection holding an exclusive lock on
// the file for its whole life: a second store (in this or another process)
// on the same file is refused, which keeps two runs from writing one output
// folder. Not thread-safe: call it from one thread (the one that drives the
// solver), including the const methods.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rackopt::record {

// Besides the bit-exact record that resume reads, every variable and every
// metric is a real column (SQLite REAL, SI) of the `evaluations` view, named
// by column_name(), so that plain SQL can filter and sort evaluations
// (docs/recorder.md, "Queries").

// The SQL column of a variable or metric name: every run of characters other
// than ASCII letters, digits and '_' becomes one '_', leading and trailing
// '_' are dropped, and a name that is then empty or starts with a digit gets
// a leading "c_": "pinion.pressure_angle" -> pinion_pressure_angle,
// "wear_life_at_R(0.9)" -> wear_life_at_R_0_9. The store appends _2, _3, ...
// when two names meet (SQL names ignore case) or a name is one of the
// view's own columns.
std::string column_name(const std::string& name);

// `name` as one SQL identifier: in double quotes, a double quote inside
// doubled (SQLite's rule), so no name can end the identifier and add SQL of
// its own. The only way a name enters the store's SQL text; values are
// always bound parameters. Throws std::invalid_argument for a NUL byte (it
// would cut the statement short).
std::string sql_identifier(const std::string& name);

// One evaluation as recorded. Every double round-trips bit for bit (stored as
// raw little-endian IEEE-754 bytes), including -0.0, denormals, infinities and
// NaN payloads inside objectives/constraints/metrics; `seconds` is stored as
// an SQLite REAL and must be finite.
struct RecordedEvaluation {
  std::int64_t id = 0;  // row id, assigned by append(): 1, 2, 3, ... in append order
  std::string phase;    // free text set by the runner: "start 0", "pareto point 3", "sweep"
  std::vector<double> x;  // design vector (SI), one value per variable of the store
  std::vector<double> objectives, inequality, equality;  // as computed; may be empty when !ok
  std::vector<std::pair<std::string, double>> metrics;   // named metric values (SI), in given order
  bool ok = true;
  std::string message;  // why a failed evaluation failed (may be set for ok ones too)
  bool gradient_probe = false;  // made for a finite-difference gradient
  double seconds = 0;           // wall time of the evaluation
  // Model warnings of this design, in the order the models gave them; any
  // text round-trips. Rows recorded by a store of schema version 1 (before
  // warnings were recorded) read back with none.
  std::vector<std::string> warnings;
  // The models computed for this design ("geometry", "stiffness_curve", ...;
  // names without commas). Rows recorded before version 3 read back with none.
  std::vector<std::string> models;
};

// The output folder already holds results this run may not touch: another
// study's evaluations, this study's without resume, or other design
// variables. A user decision (another --out, --resume, delete the file),
// not a failure of the run: the CLI exits 2 with the message.
class OutputFolderConflict : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// When buffered appends become durable (see EvaluationStore::append).
struct StoreOptions {
  std::size_t commit_every = 1000;       // commit once this many appends are pending (>= 1)
  double commit_interval_seconds = 0.2;  // ... or once an append comes this long after the last commit
  // How the caller computes study_fingerprint. Stored with it; a file whose
  // evaluations were recorded under another format is refused (its
  // fingerprints cannot be compared). A file written before formats were
  // stored counts as format "1".
  std::string fingerprint_format = "1";
  // SI unit text of each variable and metric by name ("m", "rad", "N/m",
  // "-"), written beside its real column in the `value_columns` table; a
  // name not listed gets "". Only read when a column is created.
  std::map<std::string, std::string> units;
};

class EvaluationStore {
 public:
  // Opens the store at `path`, creating the file and missing parent folders.
  //  * `study_fingerprint` identifies the study definition (the runner passes
  //    a hash of the normalized study + problem). If the file already holds
  //    evaluations recorded under another fingerprint, throws
  //    std::runtime_error saying the folder holds another study's results and
  //    to choose another --out or delete the file.
  //  * resume == false on a file that already holds evaluations of this study
  //    throws std::runtime_error suggesting --resume or another --out.
  //  * A file with no evaluation (new, or left by a run that recorded nothing)
  //    takes the given fingerprint and variable names whatever resume says.
  //  * `variable_names` (the dimension of every x) are stored in the file.
  // Also throws std::runtime_error when the file is not a rackopt evaluation
  // database or has a schema version this one does not read, and
  // OutputFolderConflict when it is held by another store. A file of the previous schema version (1, without
  // warnings) is upgraded to the current one in place, unless the open is
  // refused (then the file is left as it was); docs/recorder.md.
  static EvaluationStore open(const std::string& path, const std::string& study_fingerprint,
                              const std::vector<std::string>& variable_names, bool resume,
                              StoreOptions options = {});

  EvaluationStore(EvaluationStore&&) noexcept;
  EvaluationStore& operator=(EvaluationStore&&) noexcept;
  // Commits pending appends and closes the file (errors are swallowed here;
  // call close() to see them).
  ~EvaluationStore();

  // The earliest recorded evaluation whose x has exactly the bit pattern of
  // `x` (so -0.0 and +0.0 are different keys; a deterministic driver
  // reproduces its own bits), or nothing. Sees appends not yet committed.
  // Throws std::invalid_argument when x.size() != dimension().
  std::optional<RecordedEvaluation> find(std::span<const double> x) const;

  // Records `e` (its id is ignored) and returns the new id. The row is written
  // at once into the open transaction (find() and all() see it); it becomes
  // durable when that transaction commits, which happens within this call as
  // soon as commit_every appends are pending or commit_interval_seconds have
  // passed since the last commit, and in flush(), set_meta(), close() and the
  // destructor. A kill -9 therefore loses exactly the appends made since the
  // last commit (at most commit_every of them, all made within
  // commit_interval_seconds of the previous append that committed); nothing
  // committed is lost and no row is ever half written. Commits are fsynced
  // (synchronous=FULL), so the same holds for an OS crash or power cut.
  // Throws std::invalid_argument when e.x.size() != dimension() or e.seconds
  // is not finite; std::runtime_error when the disk write fails.
  std::int64_t append(const RecordedEvaluation& e);

  // Commits pending appends now (durable when it returns).
  void flush();
  // flush(), then closes the file; the store is unusable afterwards.
  void close();

  // Every recorded evaluation in id order.
  std::vector<RecordedEvaluation> all() const;
  // Calls `visit` for each recorded evaluation in id order without holding
  // them all in memory (for exports of big studies).
  void for_each(const std::function<void(const RecordedEvaluation&)>& visit) const;

  std::size_t size() const;            // evaluations recorded (committed or not)
  std::size_t failed_count() const;    // of which !ok
  std::size_t committed_size() const;  // evaluations already durable on disk
  // Each row carries a checksum of its bytes, written with it. Opening a
  // store with evaluations (resume) checks every row: one whose bytes no
  // longer give its checksum (a flipped bit, a hand edit) is deleted, so
  // find() does not reuse it and the design is evaluated again; this counts
  // them. Rows recorded before checksums (schema version 3 or older) cannot
  // be checked: they are kept, and counted by unchecked_rows().
  std::size_t damaged_rows_removed() const;
  // The largest id recorded so far (0 for none): rows removed at open leave
  // gaps, so ids up to it are not all present.
  std::int64_t last_id() const;
  std::size_t unchecked_rows() const;
  std::size_t dimension() const;       // variables per x
  const std::vector<std::string>& variable_names() const;
  // Every metric name seen so far, in order of first appearance.
  std::vector<std::string> metric_names() const;
  // The SI unit of each variable and metric with a real column, by name (as
  // StoreOptions::units gave it when the column was made; "" if none).
  std::map<std::string, std::string> column_units() const;
  const std::string& path() const;

  // Free key/value pairs of the study (status "running"/"finished", summary
  // JSON, ...). set_meta commits at once. Keys starting with "rackopt." are
  // reserved for the store itself (std::invalid_argument).
  void set_meta(const std::string& key, const std::string& value);
  std::optional<std::string> meta(const std::string& key) const;

 private:
  struct Impl;
  explicit EvaluationStore(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// Writes every evaluation of `store` to `path` as CSV (RFC 4180 quoting,
// '\n' line ends like the project's other CSVs),
// atomically: a temporary file in the same folder, fsynced, then renamed over
// `path`, so a reader never sees a half-written table. Columns:
//   id, phase, ok (1/0), message, gradient_probe (1/0), seconds_s,
//   one column per variable_names entry (x values, SI), named with its
//   unit as with_suffix(name, unit) ("rack.span_m") when the store has one,
//   scaled_objective_0.., scaled_inequality_0.., scaled_equality_0.. (the
//   solver's values: divided by their scales, minimized, g <= 0 feasible;
//   as many as the longest row),
//   one column per metric_names entry (SI; empty where a row lacks it),
//   named with its unit likewise ("wear_life_at_R(0.9)_s").
// Numbers are written in the shortest form that reads back to the same double.
// Throws std::invalid_argument when variable_names.size() != store.dimension(),
// std::runtime_error naming the path when the file cannot be written.
void write_evaluations_csv(const EvaluationStore& store, const std::vector<std::string>& variable_names,
                           const std::vector<std::string>& metric_names, const std::string& path);

}  // namespace rackopt::record
