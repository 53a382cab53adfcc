// One rackopt run per output folder: an exclusive flock(2) on
// `<dir>/.rackopt.lock`, held for the life of the object. The kernel drops
// it when the process dies however it dies (kill -9 included), so a lock is
// never stale; the file itself stays (removing a lock file races with the
// next run taking it). While it is held the folder's leftover temporary files
// are removed (remove_stale_temporaries: nobody else may be writing them).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace rackopt {

// The folder is in use by another rackopt run. A user decision (wait, or
// choose another --out), like the other output-folder conflicts: exit 2.
class OutputFolderInUse : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class FolderLock {
 public:
  // Creates `dir` if missing, takes the lock without waiting (throws
  // OutputFolderInUse naming the folder and the holder's pid when another
  // process holds it; std::runtime_error when the folder or lock file cannot
  // be created), writes our pid into the lock file, then removes stale
  // temporary files (their names: removed()).
  explicit FolderLock(const std::string& dir);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

  const std::vector<std::string>& removed() const { return removed_; }

 private:
  int fd_ = -1;
  std::vector<std::string> removed_;
};

}  // namespace rackopt
