// CSV export of a study's evaluations (declared in evaluation_store.hpp).
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <unordered_map>

#include "rackopt/record/evaluation_store.hpp"
#include "rackopt/core/text.hpp"

namespace rackopt::record {
namespace {

void put_field(std::string& out, const std::string& field) { out += csv_field(field); }

// Shortest text that reads back to the same double ("inf", "-inf", "nan" for
// the non-finite values a failed evaluation may carry).
void put_number(std::string& out, double v) {
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, res.ptr);
}

[[noreturn]] void io_error(const std::string& what, const std::string& path, int err) {
  throw std::runtime_error("cannot write '" + path + "': " + what + ": " + std::strerror(err));
}

// Temp file in the target's folder (same file system, so rename is atomic),
// fsynced before the rename so the new name never points at missing data.
void write_atomically(const std::string& path, const std::string& content) {
  const std::filesystem::path target(path);
  const std::filesystem::path dir = target.has_parent_path() ? target.parent_path() : ".";
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw std::runtime_error("cannot create folder '" + dir.string() + "': " + ec.message());
  std::string tmp = (dir / ("." + target.filename().string() + ".tmpXXXXXX")).string();
  const int fd = mkstemp(tmp.data());
  if (fd < 0) io_error("creating a temporary file", path, errno);
  auto give_up = [&](const char* what) {
    const int err = errno;
    ::close(fd);
    ::unlink(tmp.c_str());
    io_error(what, path, err);
  };
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      give_up("writing");
    }
    done += static_cast<std::size_t>(n);
  }
  // mkstemp creates 0600; a table is meant to be read like any other output.
  if (::fchmod(fd, 0644) != 0) give_up("setting permissions");
  if (::fsync(fd) != 0) give_up("flushing to disk");
  // Verified before it gets its name: every byte on disk, a complete last row.
  struct stat st{};
  if (::fstat(fd, &st) != 0) give_up("checking the written file");
  if (static_cast<std::size_t>(st.st_size) != content.size() || content.empty() || content.back() != '\n') {
    errno = EIO;
    give_up("the written file is incomplete");
  }
  if (::close(fd) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    io_error("closing", path, err);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    io_error("renaming the temporary file", path, err);
  }
  // Make the rename itself durable (best effort: some file systems refuse).
  const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
  if (dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
}

}  // namespace

void write_evaluations_csv(const EvaluationStore& store, const std::vector<std::string>& variable_names,
                           const std::vector<std::string>& metric_names, const std::string& path) {
  if (variable_names.size() != store.dimension()) {
    throw std::invalid_argument("write_evaluations_csv: " + std::to_string(variable_names.size()) +
                                " variable names for a study of " + std::to_string(store.dimension()) +
                                " variables");
  }
  std::size_t n_obj = 0, n_ineq = 0, n_eq = 0;
  store.for_each([&](const RecordedEvaluation& e) {
    n_obj = std::max(n_obj, e.objectives.size());
    n_ineq = std::max(n_ineq, e.inequality.size());
    n_eq = std::max(n_eq, e.equality.size());
  });

  std::string out;
  auto header = [&](const std::string& name, bool first = false) {
    if (!first) out += ',';
    put_field(out, name);
  };
  header("id", true);
  for (const char* h : {"phase", "ok", "message", "gradient_probe", "seconds"}) header(h);
  for (const auto& v : variable_names) header(v);
  for (std::size_t i = 0; i < n_obj; ++i) header("objective_" + std::to_string(i));
  for (std::size_t i = 0; i < n_ineq; ++i) header("inequality_" + std::to_string(i));
  for (std::size_t i = 0; i < n_eq; ++i) header("equality_" + std::to_string(i));
  for (const auto& m : metric_names) header(m);
  out += '\n';

  std::unordered_map<std::string, std::size_t> metric_column;
  for (std::size_t i = 0; i < metric_names.size(); ++i) metric_column.emplace(metric_names[i], i);
  std::vector<const double*> metric_cell(metric_names.size());

  store.for_each([&](const RecordedEvaluation& e) {
    out += std::to_string(e.id);
    out += ',';
    put_field(out, e.phase);
    out += e.ok ? ",1," : ",0,";
    put_field(out, e.message);
    out += e.gradient_probe ? ",1," : ",0,";
    put_number(out, e.seconds);
    for (double v : e.x) {
      out += ',';
      put_number(out, v);
    }
    auto padded = [&](const std::vector<double>& v, std::size_t width) {
      for (std::size_t i = 0; i < width; ++i) {
        out += ',';
        if (i < v.size()) put_number(out, v[i]);
      }
    };
    padded(e.objectives, n_obj);
    padded(e.inequality, n_ineq);
    padded(e.equality, n_eq);
    std::fill(metric_cell.begin(), metric_cell.end(), nullptr);
    for (const auto& [name, value] : e.metrics) {
      if (auto it = metric_column.find(name); it != metric_column.end()) metric_cell[it->second] = &value;
    }
    for (const double* cell : metric_cell) {
      out += ',';
      if (cell) put_number(out, *cell);
    }
    out += '\n';
  });
  write_atomically(path, out);
}

}  // namespace rackopt::record
