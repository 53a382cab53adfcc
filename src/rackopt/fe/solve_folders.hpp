// The folders CalculiX solves run in (rackopt-ccx-XXXXXX, ccx_runner.hpp):
// who owns one, which are kept on purpose, and removing those a killed run
// left behind. A run that ends normally removes its folder (success) or
// keeps it for inspection (a failed solve, named in the error); a run killed
// with SIGKILL, or a machine that lost power, can do neither, so the next
// run cleans up after it.
//
// Each folder holds a file `owner` ("pid <pid>" and "start <token>") written
// (atomically, by rename) right after the folder is made; the token is the
// boot id and the process's start time in clock ticks (/proc/<pid>/stat), so
// a pid the system has since given to another process does not pass for the
// owner. A kept folder holds a file `kept` with the reason.
#pragma once

#include <string>

namespace rackopt::fe {

// The start token of process `pid` ("" when it cannot be read: no /proc, no
// such process).
std::string process_start_token(int pid);

// Writes `folder`/owner naming this process. Throws std::runtime_error when
// it cannot be written.
void mark_solve_folder_owner(const std::string& folder);

// Writes `folder`/kept with `reason`, so the folder is never removed
// automatically; when that file cannot be written the owner file is removed
// instead (a folder without an owner is never removed either). Never throws.
void mark_solve_folder_kept(const std::string& folder, const std::string& reason) noexcept;

// Whether the process named by an owner file (`pid`, `token`) has ended:
// no process `pid`, or one whose start token differs from `token` (the pid
// was reused). false when it cannot be told (an empty token, /proc not
// readable): an unknown owner is treated as alive.
bool solve_folder_owner_ended(int pid, const std::string& token);

// Removes the folders rackopt-ccx-* directly under `parent` that belong to
// this user (file owner = the effective uid; not a symbolic link), hold no
// `kept` file, and hold an owner file whose process has ended. A folder
// without a readable owner file (another version's, or one whose owner is
// writing it this instant) is left alone. Returns how many were removed;
// errors (a folder that vanished, no permission) are skipped, never thrown.
int remove_abandoned_solve_folders(const std::string& parent) noexcept;

}  // namespace rackopt::fe
