// The model warnings of a study grouped by kind. One warning per design
// and many designs make hundreds of near-copies ("pinion undercut: z = 17
// < z_min = 18.3", "... z = 16 < z_min = 18.1"); grouped, each kind is one
// line with the number of designs that gave it, their evaluation ids (the
// `id` column of evaluations.csv) and one example. docs/output.md,
// "Warnings".
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace rackopt::study {

// A warning's kind: its text with every number replaced by "…" (digits
// inside a name such as z_min or R90 stay). Warnings are free text from
// many models and are stored as text in the evaluation store, so the kind
// is derived from the text: a resumed run groups recorded warnings exactly
// like fresh ones.
std::string warning_kind(const std::string& message);

struct WarningGroup {
  std::string kind;                        // warning_kind of every message in the group
  std::string example;                     // the group's first message, as the model wrote it
  std::size_t designs = 0;                 // designs (evaluations) that gave a warning of this kind
  std::size_t messages = 0;                // distinct messages of this kind
  std::vector<std::int64_t> evaluations;   // ids of the first kMaxListedEvaluations of those designs, in order
};

// Evaluation ids listed per group (the count is always complete).
inline constexpr std::size_t kMaxListedEvaluations = 100;
// Kinds kept; warnings of further kinds are only counted (a model whose
// messages carry names or paths could otherwise make one kind per design).
inline constexpr std::size_t kMaxWarningKinds = 100;

// Collects the warnings of a study design by design, in the order the
// designs are first used.
class WarningTally {
 public:
  // The warnings of the design recorded as `evaluation` (0 = no id). A
  // design with two messages of one kind counts once for that kind.
  void add(const std::vector<std::string>& warnings, std::int64_t evaluation);
  // The groups in first-use order.
  const std::vector<WarningGroup>& groups() const { return groups_; }
  // Warnings whose kind did not fit in kMaxWarningKinds.
  std::size_t dropped() const { return dropped_; }

 private:
  std::vector<WarningGroup> groups_;
  std::map<std::string, std::size_t> index_of_kind_;
  std::set<std::string> seen_message_;
  std::size_t dropped_ = 0;
};

}  // namespace rackopt::study
