#include "rackopt/output/atomic_file.hpp"

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include <fcntl.h>
#include <unistd.h>

#include "rackopt/core/atomic_file.hpp"
#include "rackopt/output/file_check.hpp"

namespace rackopt {
namespace {

namespace fs = std::filesystem;

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

void write_file_atomic(const std::string& path, const std::string& content) {
  write_file_atomically(path, content, [&](const std::string& tmp) {
    return check_output_file(tmp, path);  // the writer has checked the size
  });
}

void write_file_atomic_from(const std::string& path, const ContentProducer& produce) {
  write_file_atomically_from(path, produce, [&](const std::string& tmp) { return check_output_file(tmp, path); });
}

std::string publish_verified(const std::string& tmp, const std::string& path) {
  const std::string why = check_output_file(tmp, path);
  if (!why.empty()) {
    ::unlink(tmp.c_str());
    return why;
  }
  const int fd = ::open(tmp.c_str(), O_RDONLY | O_CLOEXEC);
  const bool synced = fd >= 0 && ::fsync(fd) == 0;
  const int err = errno;
  if (fd >= 0) ::close(fd);
  if (!synced) {
    ::unlink(tmp.c_str());
    return std::string("cannot flush it to disk: ") + std::strerror(err);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err2 = errno;
    ::unlink(tmp.c_str());
    return std::string("cannot rename it into place: ") + std::strerror(err2);
  }
  fsync_directory_of(path);
  return "";
}

bool is_rackopt_temporary(const std::string& name) {
  // "<name>.tmp.<digits>"
  const std::size_t at = name.rfind(".tmp.");
  if (at != std::string::npos && at > 0 && at + 5 < name.size()) {
    bool digits = true;
    for (std::size_t i = at + 5; i < name.size(); ++i) digits = digits && std::isdigit(static_cast<unsigned char>(name[i]));
    if (digits) return true;
  }
  // "<name>.png.tmp", "<name>.svg.tmp"
  if (name.size() > 8 && (ends_with(name, ".png.tmp") || ends_with(name, ".svg.tmp"))) return true;
  // ".<name>.tmpXXXXXX"
  if (name.size() > 11 && name[0] == '.' && name.compare(name.size() - 10, 4, ".tmp") == 0) {
    bool alnum = true;
    for (std::size_t i = name.size() - 6; i < name.size(); ++i) {
      alnum = alnum && std::isalnum(static_cast<unsigned char>(name[i]));
    }
    if (alnum) return true;
  }
  return false;
}

std::vector<std::string> remove_stale_temporaries(const std::string& dir) {
  std::vector<std::string> removed;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    std::error_code ec2;
    if (!it->is_regular_file(ec2) || !is_rackopt_temporary(name)) continue;
    if (fs::remove(it->path(), ec2)) removed.push_back(name);
  }
  return removed;
}

}  // namespace rackopt
