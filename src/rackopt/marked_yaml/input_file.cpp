#include "rackopt/marked_yaml/input_file.hpp"

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "rackopt/core/error.hpp"
#include "rackopt/core/run_limits.hpp"
#include "rackopt/marked_yaml/input_limits.hpp"

namespace rackopt {

namespace {

// What a file that is not a regular file is, for the message.
std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "a special file";
}

// Closes the descriptor on every way out.
struct FileDescriptor {
  int fd = -1;
  ~FileDescriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string read_input_file(const std::string& path, const std::string& what) {
  check_path_text(path, what);
  const SourceMark where{path, 0, 0};
  // O_NONBLOCK: opening a FIFO must not wait for a writer (it would block
  // in open(), out of reach of Ctrl-C's stop request). The type is checked
  // on the descriptor opened, so nothing can swap the file in between.
  FileDescriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0) {
    throw InputError(where, "", "cannot open the " + what + ": " + std::strerror(errno));
  }
  struct stat st{};
  if (::fstat(file.fd, &st) != 0) {
    throw InputError(where, "", "cannot read the " + what + ": " + std::strerror(errno));
  }
  if (S_ISDIR(st.st_mode)) {
    throw InputError(where, "", "is a directory, not a " + what + " (give the path of a .yaml file)");
  }
  // A FIFO, a device or a socket can block for ever or never end: only a
  // regular file is read (docs/input_limits.md).
  if (!S_ISREG(st.st_mode)) {
    throw InputError(where, "",
                     "is " + kind_of(st.st_mode) + ", not a regular file: a " + what +
                         " must be a regular file (save the text to a .yaml file and give its path)");
  }
  // Bounded even so: a regular file can grow while it is read.
  std::string text(kMaxInputBytes + 1, '\0');
  std::size_t got = 0;
  while (got < text.size()) {
    const ssize_t n = ::read(file.fd, text.data() + got, text.size() - got);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      throw InputError(where, "", "cannot read the " + what + ": " + std::strerror(errno));
    }
    got += static_cast<std::size_t>(n);
  }
  text.resize(got);
  if (text.size() > kMaxInputBytes) {
    throw InputError(where, "",
                     "the " + what + " is larger than " + std::to_string(kMaxInputBytes) +
                         " bytes (1 MiB), the limit for an input file; a " + what +
                         " is a few kB (docs/input_limits.md)");
  }
  return text;
}

}  // namespace rackopt
