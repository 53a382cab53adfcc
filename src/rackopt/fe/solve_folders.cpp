#include "rackopt/fe/solve_folders.hpp"

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

namespace rackopt::fe {
namespace {

namespace fs = std::filesystem;

constexpr const char* kOwnerFile = "owner";
constexpr const char* kKeptFile = "kept";
constexpr const char* kFolderPrefix = "rackopt-ccx-";

std::string first_line(const fs::path& p) {
  std::ifstream in(p);
  std::string line;
  std::getline(in, line);
  return line;
}

// Field 22 of /proc/<pid>/stat (start time after boot, clock ticks). The
// command name (field 2) is in parentheses and may hold spaces: count from
// the last ')'.
std::string start_ticks(int pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto close = text.rfind(')');
  if (close == std::string::npos) return "";
  std::istringstream fields(text.substr(close + 1));
  std::string f;
  for (int k = 3; k <= 22; ++k) {
    if (!(fields >> f)) return "";
  }
  return f;
}

}  // namespace

std::string process_start_token(int pid) {
  const std::string ticks = start_ticks(pid);
  if (ticks.empty()) return "";
  const std::string boot = first_line("/proc/sys/kernel/random/boot_id");
  return (boot.empty() ? std::string("boot?") : boot) + "/" + ticks;
}

void mark_solve_folder_owner(const std::string& folder) {
  const fs::path dir(folder);
  const fs::path tmp = dir / (std::string(kOwnerFile) + ".tmp");
  {
    std::ofstream out(tmp);
    out << "pid " << ::getpid() << "\nstart " << process_start_token(static_cast<int>(::getpid())) << "\n";
    out.flush();
    if (!out) throw std::runtime_error("cannot write " + tmp.string());
  }
  std::error_code ec;
  fs::rename(tmp, dir / kOwnerFile, ec);
  if (ec) throw std::runtime_error("cannot write " + (dir / kOwnerFile).string() + ": " + ec.message());
}

void mark_solve_folder_kept(const std::string& folder, const std::string& reason) noexcept {
  try {
    const fs::path dir(folder);
    bool written = false;
    {
      std::ofstream out(dir / kKeptFile);
      out << "kept for inspection: " << reason << "\n";
      out.flush();
      written = static_cast<bool>(out);
    }
    if (!written) {
      std::error_code ec;
      fs::remove(dir / kOwnerFile, ec);
    }
  } catch (...) {
  }
}

bool solve_folder_owner_ended(int pid, const std::string& token) {
  if (pid <= 0) return false;
  if (::kill(pid, 0) != 0 && errno == ESRCH) return true;
  if (token.empty()) return false;
  const std::string now = process_start_token(pid);
  return !now.empty() && now != token;
}

int remove_abandoned_solve_folders(const std::string& parent) noexcept {
  int removed = 0;
  try {
    std::error_code ec;
    for (fs::directory_iterator it(parent, ec), end; !ec && it != end; it.increment(ec)) {
      const fs::path dir = it->path();
      if (dir.filename().string().rfind(kFolderPrefix, 0) != 0) continue;
      struct stat st {};
      if (::lstat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode) || st.st_uid != ::geteuid()) continue;
      std::error_code e2;
      if (fs::exists(dir / kKeptFile, e2) || e2) continue;
      std::ifstream in(dir / kOwnerFile);
      std::string key_pid, key_start, token;
      long pid = 0;
      if (!(in >> key_pid >> pid) || key_pid != "pid") continue;
      if (in >> key_start) {
        if (key_start != "start") continue;
        in >> token;  // may be absent: an owner that could not read its own start
      }
      if (!solve_folder_owner_ended(static_cast<int>(pid), token)) continue;
      fs::remove_all(dir, e2);
      if (!e2) ++removed;
    }
  } catch (...) {
  }
  return removed;
}

}  // namespace rackopt::fe
