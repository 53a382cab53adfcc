#include "rackopt/core/atomic_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "rackopt/core/interrupt.hpp"

namespace rackopt {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& path, const std::string& what, int err) {
  throw std::runtime_error("cannot write " + path + ": " + what + (err ? std::string(": ") + std::strerror(err) : ""));
}

}  // namespace

void fsync_directory_of(const std::string& path) {
  const fs::path dir = fs::path(path).parent_path();
  const int dfd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
}

void write_file_atomically(const std::string& path, std::string_view content, const WrittenFileCheck& check) {
  if (content.empty()) fail(path, "refusing to write an empty file", 0);
  write_file_atomically_from(path, [&](const std::function<void(std::string_view)>& write) { write(content); }, check);
}

void write_file_atomically_from(const std::string& path, const ContentProducer& produce, const WrittenFileCheck& check) {
  const fs::path target(path);
  const fs::path dir = target.parent_path();
  if (!dir.empty()) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) throw std::runtime_error("cannot create directory " + dir.string() + ": " + ec.message());
  }
  std::string tmp = ((dir.empty() ? fs::path(".") : dir) / ("." + target.filename().string() + ".tmpXXXXXX")).string();
  const int fd = ::mkostemp(tmp.data(), O_CLOEXEC);
  if (fd < 0) fail(path, "creating a temporary file", errno);
  const TemporaryFileGuard guard(tmp);  // a second Ctrl-C unlinks it
  bool open = true;
  auto give_up = [&](const std::string& what, int err) {
    open = false;
    ::close(fd);
    ::unlink(tmp.c_str());
    fail(path, what, err);
  };
  std::size_t total = 0;
  const auto write = [&](std::string_view piece) {
    std::size_t done = 0;
    while (done < piece.size()) {
      const ssize_t n = ::write(fd, piece.data() + done, piece.size() - done);
      if (n < 0) {
        if (errno == EINTR) continue;
        give_up("writing", errno);
      }
      if (n == 0) give_up("writing", EIO);
      done += static_cast<std::size_t>(n);
    }
    total += piece.size();
  };
  try {
    produce(write);
  } catch (...) {
    if (open) {  // else give_up has closed and removed it already
      ::close(fd);
      ::unlink(tmp.c_str());
    }
    throw;
  }
  if (total == 0) give_up("refusing to write an empty file", 0);
  // mkostemp creates 0600; an output is meant to be read like any other file.
  if (::fchmod(fd, 0644) != 0) give_up("setting permissions", errno);
  if (::fsync(fd) != 0) give_up("flushing to disk", errno);
  struct stat st{};
  if (::fstat(fd, &st) != 0) give_up("checking the written file", errno);
  if (static_cast<std::size_t>(st.st_size) != total) give_up("the written file is incomplete", EIO);
  if (::close(fd) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    fail(path, "closing", err);
  }
  if (check) {
    const std::string why = check(tmp);
    if (!why.empty()) {
      ::unlink(tmp.c_str());
      fail(path, "the written file failed its check: " + why, 0);
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    fail(path, "renaming the temporary file", err);
  }
  fsync_directory_of(path);
}

}  // namespace rackopt
