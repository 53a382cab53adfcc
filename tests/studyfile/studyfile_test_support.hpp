// Small helpers several study-file tests share (one definition, so the test
// files can be compiled together in a unity build).
#pragma once

#include <string>
#include <vector>

#include "rackopt/studyfile/study_loader.hpp"

namespace rackopt::test {

// studies/ of the source tree: the folder a test study text is read from.
inline const std::string kStudies = std::string(RACKOPT_SOURCE_DIR) + "/studies";

// Loads the study `text` as "t.yaml" in studies/ with `overrides`.
inline study::StudySpec load(const std::string& text, const std::vector<std::string>& overrides = {}) {
  return studyfile::load_study_text(text, "t.yaml", kStudies, overrides);
}

}  // namespace rackopt::test
