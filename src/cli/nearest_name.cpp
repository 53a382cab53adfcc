// The "did you mean" of usage errors: a mistyped option or command is most
// often one or two keystrokes away from the meant one (a letter missing,
// doubled, wrong or two letters swapped), so the edit distance that counts
// an adjacent swap as one edit finds it.
#include <algorithm>
#include <string>
#include <vector>

#include "cli.hpp"

namespace rackopt::cli {
namespace {

// Optimal string alignment distance: insertions, deletions, substitutions
// and swaps of adjacent characters cost one each.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1, 0));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[n][m];
}

std::string without_dashes(const std::string& s) { return s.substr(std::min(s.find_first_not_of('-'), s.size())); }

}  // namespace

std::string nearest_name(const std::string& given, const std::vector<std::string>& candidates) {
  const std::string word = without_dashes(given);
  // A third of the word may be wrong: "thread" finds "threads", "bogus"
  // finds nothing rather than an unrelated "out".
  const std::size_t allowed = std::max<std::size_t>(1, word.size() / 3);
  std::string best;
  std::size_t best_distance = allowed + 1;
  for (const std::string& c : candidates) {
    const std::size_t dist = edit_distance(word, without_dashes(c));
    if (dist < best_distance) {
      best = c;
      best_distance = dist;
    }
  }
  return best;
}

}  // namespace rackopt::cli
