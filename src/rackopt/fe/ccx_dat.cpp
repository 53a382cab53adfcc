#include "rackopt/fe/ccx_dat.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace rackopt::fe {
namespace {

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// Whitespace-separated words of `line`.
std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> w;
  std::string s;
  while (in >> s) w.push_back(s);
  return w;
}

// Fortran drops the E of a three-digit exponent ("0.123456-100"): put it back.
bool parse_number(const std::string& s, double& v) {
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  if (end != s.c_str() && *end == '\0') return true;
  if (end != s.c_str() && (*end == '-' || *end == '+') && std::isdigit(static_cast<unsigned char>(end[-1]))) {
    const std::string fixed = s.substr(0, static_cast<std::size_t>(end - s.c_str())) + "E" + end;
    v = std::strtod(fixed.c_str(), &end);
    return *end == '\0';
  }
  return false;
}

}  // namespace

std::vector<DatBlock> parse_ccx_dat(const std::string& text, const std::string& file_name) {
  std::vector<DatBlock> blocks;
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  enum class Expect { none, rows, total, statistics } expect = Expect::none;
  const auto fail = [&](const std::string& what) {
    throw std::runtime_error(file_name + ":" + std::to_string(line_no) + ": " + what);
  };
  while (std::getline(in, line)) {
    ++line_no;
    const std::vector<std::string> w = words(line);
    if (w.empty()) continue;
    if (line.find("statistics for slave set ") != std::string::npos) {
      expect = Expect::statistics;  // read by parse_ccx_contact_statistics
      continue;
    }
    // Header: "<quantity words> (a,b,c) for set NAME and time T"
    const auto for_at = line.find(" for set ");
    if (for_at != std::string::npos) {
      const auto and_at = line.find(" and time ", for_at);
      if (and_at == std::string::npos) fail("block header without a time: " + line);
      const std::vector<std::string> head = words(line.substr(0, for_at));
      const std::vector<std::string> set_words = words(line.substr(for_at + 9, and_at - for_at - 9));
      double t = 0;
      const std::vector<std::string> tail = words(line.substr(and_at + 10));
      if (head.empty() || set_words.size() != 1 || tail.size() != 1 || !parse_number(tail[0], t)) {
        fail("unreadable block header: " + line);
      }
      if (head[0] == "total") {
        // The sum that follows belongs to the last block of that set.
        if (blocks.empty() || upper(blocks.back().set) != upper(set_words[0])) fail("a total with no block before it");
        expect = Expect::total;
        continue;
      }
      DatBlock b;
      b.quantity = head[0];
      b.set = set_words[0];
      b.time = t;
      blocks.push_back(b);
      expect = Expect::rows;
      continue;
    }
    if (expect == Expect::statistics) continue;
    if (expect == Expect::none) fail("data outside any block: " + line);
    std::array<double, 3> v{};
    const std::size_t first = expect == Expect::total ? 0 : 1;
    if (w.size() != first + 3) fail("expected " + std::to_string(first + 3) + " numbers: " + line);
    for (std::size_t k = 0; k < 3; ++k) {
      if (!parse_number(w[first + k], v[k])) fail("not a number '" + w[first + k] + "': " + line);
      if (!std::isfinite(v[k])) fail("non-finite value (the solve diverged?): " + line);
    }
    if (expect == Expect::total) {
      blocks.back().has_total = true;
      blocks.back().total = v;
      expect = Expect::none;
    } else {
      char* end = nullptr;
      const long node = std::strtol(w[0].c_str(), &end, 10);
      if (*end != '\0' || node <= 0) fail("not a node number '" + w[0] + "': " + line);
      blocks.back().rows.emplace_back(static_cast<int>(node), v);
    }
  }
  return blocks;
}

std::vector<ContactStatistics> parse_ccx_contact_statistics(const std::string& text, const std::string& file_name) {
  std::vector<ContactStatistics> out;
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  std::vector<double> numbers;  // of the current section
  bool open = false;
  const auto fail = [&](const std::string& what) {
    throw std::runtime_error(file_name + ":" + std::to_string(line_no) + ": " + what);
  };
  const auto close = [&]() {
    if (!open) return;
    if (numbers.size() != 18) fail("contact statistics with " + std::to_string(numbers.size()) + " numbers, not 18");
    ContactStatistics& c = out.back();
    for (int k = 0; k < 3; ++k) {
      c.force[k] = numbers[k];
      c.moment[k] = numbers[3 + k];
      c.centre[k] = numbers[6 + k];
    }
    c.area = numbers[15];
    c.normal_force = numbers[16];
    c.shear_force = numbers[17];
    if (c.area == 0) {
      c.normal_force = c.shear_force = 0;
    } else if (!std::isfinite(c.normal_force) || !std::isfinite(c.shear_force)) {
      fail("non-finite contact force with contact area " + std::to_string(c.area) + " (the solve diverged?)");
    }
    open = false;
  };
  while (std::getline(in, line)) {
    ++line_no;
    const auto at = line.find("statistics for slave set ");
    if (at != std::string::npos) {
      close();
      // "statistics for slave set S, master set M and time T"
      const auto master_at = line.find(", master set ", at);
      const auto time_at = line.find(" and time ", at);
      if (master_at == std::string::npos || time_at == std::string::npos || time_at < master_at) {
        fail("unreadable contact statistics header: " + line);
      }
      ContactStatistics c;
      const std::vector<std::string> slave = words(line.substr(at + 25, master_at - at - 25));
      const std::vector<std::string> master = words(line.substr(master_at + 13, time_at - master_at - 13));
      const std::vector<std::string> t = words(line.substr(time_at + 10));
      if (slave.size() != 1 || master.size() != 1 || t.size() != 1 || !parse_number(t[0], c.time)) {
        fail("unreadable contact statistics header: " + line);
      }
      c.slave = slave[0];
      c.master = master[0];
      out.push_back(c);
      numbers.clear();
      open = true;
      continue;
    }
    if (!open) continue;
    if (line.find(" for set ") != std::string::npos) {  // the next ordinary block
      close();
      continue;
    }
    const std::vector<std::string> w = words(line);
    if (w.empty()) continue;
    double v = 0;
    if (!parse_number(w[0], v)) continue;  // a caption line
    for (const std::string& x : w) {
      if (!parse_number(x, v)) fail("not a number '" + x + "': " + line);
      // A pair without contact has zero area: its centre of gravity, mean
      // normal, the moment about it and its normal and shear force (per
      // area) come out 0/0 (NaN). The total force and the area must be finite.
      const std::size_t k = numbers.size();
      if (!std::isfinite(v) && (k < 6 || k == 15)) fail("non-finite value (the solve diverged?): " + line);
      numbers.push_back(v);
    }
  }
  close();
  return out;
}

const DatBlock& find_dat_block(const std::vector<DatBlock>& blocks, const std::string& quantity,
                               const std::string& set) {
  for (auto it = blocks.rbegin(); it != blocks.rend(); ++it) {
    if (it->quantity == quantity && upper(it->set) == upper(set)) return *it;
  }
  throw std::runtime_error("the CalculiX output has no " + quantity + " for set " + set);
}

}  // namespace rackopt::fe
