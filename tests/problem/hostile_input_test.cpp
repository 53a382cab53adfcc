// Hostile and broken input: every case here used to hang, exhaust memory,
// fail deep in the model with an unexpected exception, or report the wrong
// thing. Each is refused in bounded time with file:line:column and a message
// that says what is wrong (docs/input_limits.md).
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <future>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include "problem_test_support.hpp"
#include "rackopt/marked_yaml/input_file.hpp"
#include "rackopt/marked_yaml/input_limits.hpp"
#include "rackopt/marked_yaml/marked_tree.hpp"
#include "rackopt/problem/problem_loader.hpp"
#include "rackopt/units/units.hpp"
#include "support/scratch_dir.hpp"

namespace rackopt {
namespace {

using test::kMinimal;

// Runs `load` and returns the InputError it throws (fails the test if none).
template <typename F>
InputError input_error(F load) {
  try {
    load();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError";
  return InputError(SourceMark{}, "", "");
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A ceiling on this process's address space for one test: a regression to
// unbounded memory then fails fast with std::bad_alloc instead of eating the
// machine (the original defects grew to several GB). ASan reserves terabytes
// of address space up front, so the ceiling is skipped under it.
class AddressSpaceCeiling {
 public:
  explicit AddressSpaceCeiling(rlim_t bytes) {
#if defined(__SANITIZE_ADDRESS__)
    (void)bytes;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
    (void)bytes;
#else
    set(bytes);
#endif
#else
    set(bytes);
#endif
  }
  ~AddressSpaceCeiling() {
    if (active_) setrlimit(RLIMIT_AS, &saved_);
  }

 private:
  void set(rlim_t bytes) {
    if (getrlimit(RLIMIT_AS, &saved_) != 0) return;
    rlimit limited = saved_;
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    // Room for what the process already maps (gtest, libraries) plus `bytes`.
    std::ifstream status("/proc/self/statm");
    unsigned long pages = 0;
    status >> pages;
    const rlim_t want = static_cast<rlim_t>(pages) * 4096 + bytes;
    if (saved_.rlim_max != RLIM_INFINITY && want > saved_.rlim_max) return;
    limited.rlim_cur = want;
    active_ = setrlimit(RLIMIT_AS, &limited) == 0;
  }
  rlimit saved_{};
  bool active_ = false;
};

// ---------------------------------------------------------------- a stray ','

// yaml-cpp 0.7 reads a document starting with ',' as endless empty documents:
// YAML::LoadAll never returned and grew to GBs before std::bad_alloc.
TEST(StrayComma, OneByteFileIsRefusedAtTheComma) {
  const AddressSpaceCeiling ceiling(512u << 20);
  const InputError e = input_error([] { load_problem_text(",", "t.yaml"); });
  EXPECT_EQ(e.mark().file, "t.yaml");
  EXPECT_EQ(e.mark().line, 1);
  EXPECT_EQ(e.mark().column, 1);
  EXPECT_TRUE(contains(e.message(), "a ',' outside a [list] or {map}")) << e.what();
}

TEST(StrayComma, CommentThatLostItsHashPointsAtTheComma) {
  const AddressSpaceCeiling ceiling(512u << 20);
  const InputError e = input_error([] { load_problem_text("\n   , y: 2\n", "t.yaml"); });
  EXPECT_EQ(e.mark().line, 2);
  EXPECT_EQ(e.mark().column, 4);
  EXPECT_TRUE(contains(e.message(), "','")) << e.what();
}

TEST(StrayComma, SetValueThatIsOnlyACommaNamesTheCommandLine) {
  const AddressSpaceCeiling ceiling(512u << 20);
  const InputError e = input_error([] { load_problem_text(kMinimal, "t.yaml", {"rack.span=,"}); });
  EXPECT_EQ(e.mark().file, "<command line>");
  EXPECT_EQ(e.mark().line, 0);
  EXPECT_TRUE(contains(e.message(), "a ',' outside")) << e.what();
}

TEST(StrayComma, AfterAFlowValueAndAfterAnExplicitDocumentStart) {
  const AddressSpaceCeiling ceiling(512u << 20);
  // "[1]," : the first document is the list, the ',' starts the endless rest.
  InputError e = input_error([] { parse_marked_yaml("[1],", "t.yaml"); });
  EXPECT_EQ(e.mark().column, 4);
  EXPECT_TRUE(contains(e.message(), "a ',' outside")) << e.what();
  e = input_error([] { parse_marked_yaml("--- ,", "t.yaml"); });
  EXPECT_EQ(e.mark().column, 5);
  EXPECT_TRUE(contains(e.message(), "a ',' outside")) << e.what();
}

TEST(StrayComma, RealSecondDocumentKeepsItsOwnMessage) {
  const InputError e = input_error([] { parse_marked_yaml("a: 1\n---\nb: 2\n", "t.yaml"); });
  EXPECT_EQ(e.mark().line, 2);
  EXPECT_TRUE(contains(e.message(), "more than one YAML document")) << e.what();
  // A comma inside a text or a flow list is ordinary YAML.
  const MarkedNode ok = parse_marked_yaml("a: x, y\nb: [1, 2]\n", "t.yaml");
  EXPECT_EQ(ok.find("a")->scalar, "x, y");
  EXPECT_EQ(ok.find("b")->items.size(), 2u);
}

// ---------------------------------------------------------------- alias fan-out

// One anchor on a 300 kB scalar, 3000 aliases: 3000 nodes (under the node
// limit) but 900 MB of text once expanded; the old loader peaked near 0.9 GB.
TEST(AliasFanOut, LargeScalarRepeatedByAliasesIsRefusedByExpandedSize) {
  const AddressSpaceCeiling ceiling(512u << 20);
  std::string text = "description: &a " + std::string(300000, 'x') + "\nnames:\n";
  for (int i = 0; i < 3000; ++i) text += "  - *a\n";
  ASSERT_LT(text.size(), kMaxInputBytes);
  const InputError e = input_error([&] { load_problem_text(text, "t.yaml"); });
  EXPECT_TRUE(contains(e.message(), "once aliases are expanded")) << e.what();
  EXPECT_TRUE(contains(e.message(), std::to_string(kMaxExpandedTextBytes))) << e.what();
  // Points at the alias that crossed the limit: the anchor and 6 copies hold
  // 2.1e6 > 2097152 bytes; aliases start on line 3, the 6th is on line 8.
  EXPECT_EQ(e.mark().line, 8) << e.what();
}

TEST(AliasFanOut, SubtreeAnchorCountsEveryNodeOfEachCopy) {
  // 100 nodes under the anchor, 300 aliases: 30000 nodes after expansion.
  std::string text = "base: &a [";
  for (int i = 0; i < 99; ++i) text += "x, ";
  text += "x]\ncopies:\n";
  for (int i = 0; i < 300; ++i) text += "  - *a\n";
  const InputError e = input_error([&] { parse_marked_yaml(text, "t.yaml"); });
  EXPECT_TRUE(contains(e.message(), "more than " + std::to_string(kMaxTreeNodes) + " nodes")) << e.what();
}

TEST(AliasFanOut, ModestAliasesStillWork) {
  const MarkedNode tree = parse_marked_yaml("a: &a {E: 210 GPa, nu: 0.3}\nb: *a\nc: *a\n", "t.yaml");
  EXPECT_EQ(tree.find("c")->find("E")->scalar, "210 GPa");
}

TEST(AliasFanOut, AliasInsideItsOwnAnchorIsACycle) {
  const InputError e = input_error([] { parse_marked_yaml("a: &a [1, *a]\n", "t.yaml"); });
  EXPECT_TRUE(contains(e.message(), "cycle")) << e.what();
}

// ---------------------------------------------------------------- input size

TEST(InputSize, TextOverTheLimitIsRefusedBeforeParsing) {
  const std::string text = "description: " + std::string(kMaxInputBytes, 'x') + "\n";
  const InputError e = input_error([&] { load_problem_text(text, "t.yaml"); });
  EXPECT_EQ(e.mark().line, 1);
  EXPECT_TRUE(contains(e.message(), "at most " + std::to_string(kMaxInputBytes) + " bytes")) << e.what();
}

TEST(InputSize, FileOverTheLimitIsRefusedReadingBounded) {
  const std::string path = test_support::scratch_dir("hostile") + "/big.yaml";
  {
    std::ofstream out(path, std::ios::binary);
    out << "description: " << std::string(kMaxInputBytes, 'x') << "\n";
  }
  const InputError e = input_error([&] { load_problem(path); });
  std::filesystem::remove(path);
  EXPECT_EQ(e.mark().file, path);
  EXPECT_TRUE(contains(e.message(), "larger than " + std::to_string(kMaxInputBytes) + " bytes")) << e.what();
}

TEST(InputSize, EndlessDeviceIsRefusedUnread) {
  const AddressSpaceCeiling ceiling(512u << 20);
  if (!std::filesystem::exists("/dev/zero")) GTEST_SKIP() << "no /dev/zero";
  const InputError e = input_error([] { read_input_file("/dev/zero", "problem file"); });
  EXPECT_EQ(e.mark().file, "/dev/zero");
  EXPECT_TRUE(contains(e.message(), "is a character device, not a regular file")) << e.what();
}

// A FIFO without a writer blocks a plain open() for ever. The read runs on
// a thread; should it still wait after 10 s, the test opens the FIFO's
// write end and closes it (the reader then sees an empty file), so that a
// regression fails instead of hanging.
TEST(InputSize, FifoIsRefusedWithoutWaitingForAWriter) {
  const std::string path = test_support::scratch_dir("hostile") + "/problem.fifo";
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
  std::promise<std::string> answer;
  std::future<std::string> got = answer.get_future();
  std::thread reader([&] {
    try {
      read_input_file(path, "problem file");
      answer.set_value("read without an error");
    } catch (const InputError& e) {
      answer.set_value(e.what());
    }
  });
  const bool in_time = got.wait_for(std::chrono::seconds(10)) == std::future_status::ready;
  if (!in_time) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK);
    if (fd >= 0) ::close(fd);
  }
  reader.join();
  const std::string message = got.get();
  std::filesystem::remove(path);
  EXPECT_TRUE(in_time) << "read_input_file waited on the FIFO";
  EXPECT_TRUE(contains(message, path)) << message;
  EXPECT_TRUE(contains(message, "is a FIFO (named pipe), not a regular file")) << message;
}

TEST(InputSize, DirectoryIsNamedAsADirectory) {
  const std::string dir = std::string(RACKOPT_SOURCE_DIR) + "/problems";
  const InputError e = input_error([&] { load_problem(dir); });
  EXPECT_EQ(e.mark().file, dir);
  EXPECT_TRUE(contains(e.message(), "is a directory")) << e.what();
  EXPECT_FALSE(contains(e.message(), "required key")) << e.what();
}

// ---------------------------------------------------------------- plausibility ranges

struct RangeCase {
  std::vector<std::string> assignments;  // --set over kMinimal
  std::string key;          // the key the error must name
  std::string fragment;     // part of the allowed range in the message
};

// Tiny positive values used to pass the loader and then fail in the model
// (exit 1) or name another key; each is now refused at its own key.
TEST(Plausibility, TinyPositiveValuesAreRefusedAtTheirKey) {
  const std::vector<RangeCase> cases = {
      {{"rack.body_height=1e-300 mm"}, "rack.body_height", "0.1 mm <= body_height"},
      {{"rack.body_height=", "rack.section={area: 3600 mm^2, second_moment: 5e-324 m^4, neutral_axis_depth: 40 mm}"},
       "rack.section.second_moment", "<= second_moment"},
      {{"materials.steel={E: 5e-324 Pa, nu: 0.3}"},
       "materials.steel.E",
       "4.94066e-333 GPa is out of range; allowed: 0.1 GPa <= E <= 1200 GPa"},
      {{"pinion.face_width=1e-200 mm"}, "pinion.face_width", "0.1 mm <= face_width"},
      {{"rack.span=1e-9 m"}, "rack.span", "1 mm <= span"},
      {{"load.force=1e-300 N"}, "load.force", "<= force"},
      {{"load.efficiency=1e-12"}, "load.efficiency", "0.05 <= efficiency <= 1"},
      {{"pinion.addendum=1e-300"}, "pinion.addendum", "0.1 <= addendum"},
      {{"rack.root_radius=1e-300 mm"}, "rack.root_radius", "(0 = the pinion cutter tip radius)"},
      {{"duty.rack_meshes_per_year=1e4", "duty.pinion_meshes_per_year=1e-300"}, "duty.pinion_meshes_per_year",
       "(or 0 for the default)"},
  };
  for (const auto& c : cases) {
    const InputError e = input_error([&] { load_problem_text(kMinimal, "t.yaml", c.assignments); });
    EXPECT_EQ(e.key_path(), c.key) << c.assignments.back() << ": " << e.what();
    EXPECT_EQ(e.mark().file, "<command line>") << e.what();
    EXPECT_TRUE(contains(e.message(), "is out of range; allowed: ")) << e.what();
    EXPECT_TRUE(contains(e.message(), c.fragment)) << c.assignments.back() << ": " << e.what();
  }
}

TEST(Plausibility, ZeroStillMeansTheDefaultWhereDocumented) {
  const Drive d = load_problem_text(kMinimal, "t.yaml", {"rack.root_radius=0"});
  EXPECT_EQ(d.rack.root_radius, 0.0);
}

TEST(Plausibility, FileMarkPointsAtTheValue) {
  std::string text = kMinimal;
  text.replace(text.find("80 mm"), 5, "1e-300 mm");
  const InputError e = input_error([&] { load_problem_text(text, "t.yaml"); });
  EXPECT_EQ(e.mark().line, 6);
  EXPECT_EQ(e.mark().column, 16);
  EXPECT_EQ(e.key_path(), "rack.body_height");
}

TEST(Plausibility, ShippedProblemsAndEveryVariantStayInside) {
  for (const auto& entry : std::filesystem::directory_iterator(std::string(RACKOPT_SOURCE_DIR) + "/problems")) {
    if (entry.path().extension() != ".yaml") continue;
    EXPECT_NO_THROW(load_problem_tree_file(entry.path().string())) << entry.path();
  }
}

// ---------------------------------------------------------------- messages

TEST(Messages, HugeCountIsOutOfRangeNotAFraction) {
  const InputError e = input_error([] { load_problem_text(kMinimal, "t.yaml", {"pinion.teeth=2147483648"}); });
  EXPECT_EQ(e.key_path(), "pinion.teeth");
  EXPECT_TRUE(contains(e.message(), "2147483648 is out of range; allowed: 5 <= teeth <= 1000")) << e.what();
  EXPECT_FALSE(contains(e.message(), "not a whole number")) << e.what();
  // A count without a key range still says "out of range".
  const InputError c = input_error([] { parse_count("2147483648"); });
  EXPECT_TRUE(contains(c.message(), "out of range")) << c.what();
}

TEST(Messages, HugeLengthIsPrintedNotInf) {
  const InputError e = input_error([] { load_problem_text(kMinimal, "t.yaml", {"rack.span=1e308 m"}); });
  EXPECT_TRUE(contains(e.message(), "1e+311 mm is out of range")) << e.what();
  EXPECT_FALSE(contains(e.message(), "inf")) << e.what();
  EXPECT_EQ(format_length_mm(1e308), "1e+311 mm");
  EXPECT_EQ(format_quantity(5e-324, QuantityKind::kModulus), "4.94066e-333 GPa");
  EXPECT_EQ(format_quantity(std::numeric_limits<double>::infinity(), QuantityKind::kLength), "inf mm");
}

// ---------------------------------------------------------------- clearance

// Clearance 0 is the zero-backlash mesh (the pinion is generated by the
// rack's own profile); closer, the flanks overlap. The geometry refuses a
// negative clearance, so the loader does too, at the key.
TEST(Clearance, NegativeIsRefusedAtLoadLikeTheGeometryDoes) {
  const InputError e = input_error([] { load_problem_text(kMinimal, "t.yaml", {"mounting.clearance=-1 mm"}); });
  EXPECT_EQ(e.key_path(), "mounting.clearance");
  EXPECT_TRUE(contains(e.message(), "allowed: 0 mm <= clearance")) << e.what();
  EXPECT_TRUE(contains(e.message(), "zero backlash")) << e.what();
  EXPECT_DOUBLE_EQ(load_problem_text(kMinimal, "t.yaml", {"mounting.clearance=10 mm"}).mounting.clearance, 0.010);
}

}  // namespace
}  // namespace rackopt
