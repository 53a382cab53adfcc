// rackopt wear: not wired yet (issue 3 in progress).
#include <iostream>

#include "cli.hpp"

namespace rackopt::cli {

int cmd_wear(const Args&) {
  std::cerr << "rackopt: the wear command is being built (issue 3)\n";
  return kRunFailed;
}

}  // namespace rackopt::cli
