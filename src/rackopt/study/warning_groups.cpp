#include "rackopt/study/warning_groups.hpp"

#include <cctype>
#include <set>

namespace rackopt::study {
namespace {

bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool is_word(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

// Length of the number (sign, digits, fraction, exponent) starting at i, 0
// when none starts there or it is part of a word (z_min, R90, v2).
std::size_t number_length(const std::string& s, std::size_t i) {
  if (i > 0 && is_word(s[i - 1])) return 0;
  // "v1.2", "file.3": a dot after a word joins this number to it ("0.55..3" is two numbers).
  if (i > 1 && s[i - 1] == '.' && is_word(s[i - 2])) return 0;
  std::size_t j = i;
  if (s[j] == '-' || s[j] == '+') ++j;
  const std::size_t mantissa = j;
  while (j < s.size() && is_digit(s[j])) ++j;
  if (j + 1 < s.size() && s[j] == '.' && is_digit(s[j + 1])) {
    ++j;
    while (j < s.size() && is_digit(s[j])) ++j;
  }
  if (j == mantissa) return 0;
  if (j < s.size() && (s[j] == 'e' || s[j] == 'E')) {
    std::size_t k = j + 1;
    if (k < s.size() && (s[k] == '-' || s[k] == '+')) ++k;
    if (k < s.size() && is_digit(s[k])) {
      while (k < s.size() && is_digit(s[k])) ++k;
      j = k;
    }
  }
  // "3rd", "2x": a number glued to letters is a word.
  if (j < s.size() && is_word(s[j])) return 0;
  return j - i;
}

}  // namespace

std::string warning_kind(const std::string& message) {
  std::string out;
  out.reserve(message.size());
  for (std::size_t i = 0; i < message.size();) {
    const std::size_t n = number_length(message, i);
    if (n == 0) {
      out += message[i++];
    } else {
      out += "…";
      i += n;
    }
  }
  return out;
}

void WarningTally::add(const std::vector<std::string>& warnings, std::int64_t evaluation) {
  std::set<std::size_t> counted;  // kinds this design already counted for
  for (const std::string& w : warnings) {
    const std::string kind = warning_kind(w);
    auto it = index_of_kind_.find(kind);
    if (it == index_of_kind_.end()) {
      if (groups_.size() >= kMaxWarningKinds) {
        ++dropped_;
        continue;
      }
      it = index_of_kind_.emplace(kind, groups_.size()).first;
      WarningGroup g;
      g.kind = kind;
      g.example = w;
      groups_.push_back(std::move(g));
    }
    WarningGroup& g = groups_[it->second];
    if (seen_message_.insert(w).second) ++g.messages;
    if (!counted.insert(it->second).second) continue;
    ++g.designs;
    if (evaluation > 0 && g.evaluations.size() < kMaxListedEvaluations) g.evaluations.push_back(evaluation);
  }
}

}  // namespace rackopt::study
