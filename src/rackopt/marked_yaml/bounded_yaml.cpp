#include "rackopt/marked_yaml/bounded_yaml.hpp"

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>

#include <cstdint>
#include <map>
#include <sstream>
#include <vector>

#include "rackopt/core/error.hpp"
#include "rackopt/marked_yaml/input_limits.hpp"

namespace rackopt {
namespace {

// Thrown out of the event handler to stop yaml-cpp's parser at once.
struct LimitExceeded {
  YAML::Mark mark;
  std::string message;
};

// Counts what the document would become once every alias is replaced by a
// copy of its anchor's value (which is what the marked tree does), without
// building anything: per anchor its expanded size, per alias that size added.
class ExpansionCounter : public YAML::EventHandler {
 public:
  int documents = 0;
  YAML::Mark second_document;

  void OnDocumentStart(const YAML::Mark& mark) override {
    if (++documents == 2) second_document = mark;
  }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override { leaf(mark, anchor, 0); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor, const std::string& value) override {
    leaf(mark, anchor, value.size());
  }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    for (const auto& o : open_) {
      if (o.anchor == anchor) {
        throw LimitExceeded{mark, "an alias inside the value its anchor names (a cycle): the value would be infinite"};
      }
    }
    const auto it = anchors_.find(anchor);
    add(mark, it != anchors_.end() ? it->second : Size{1, 0});
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    open(mark, anchor);
  }
  void OnSequenceEnd() override { close(); }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value) override {
    open(mark, anchor);
  }
  void OnMapEnd() override { close(); }

 private:
  struct Size {
    std::uint64_t nodes = 0;
    std::uint64_t bytes = 0;
  };
  struct Open {
    YAML::anchor_t anchor;
    Size before;
  };

  // Every total stays within the limits (checked after each addition), and
  // an anchor's size is part of the total, so the sums cannot overflow.
  void add(const YAML::Mark& mark, Size s) {
    total_.nodes += s.nodes;
    total_.bytes += s.bytes;
    if (total_.nodes > static_cast<std::uint64_t>(kMaxTreeNodes)) {
      throw LimitExceeded{mark, "the document expands to more than " + std::to_string(kMaxTreeNodes) +
                                    " nodes once aliases are expanded (alias fan-out?); a problem file needs a few "
                                    "hundred (docs/input_limits.md)"};
    }
    if (total_.bytes > kMaxExpandedTextBytes) {
      throw LimitExceeded{mark, "the document's keys and values add up to more than " +
                                    std::to_string(kMaxExpandedTextBytes) +
                                    " bytes once aliases are expanded (an anchor on a long value repeated by "
                                    "aliases?); a problem file holds a few kB (docs/input_limits.md)"};
    }
  }
  void leaf(const YAML::Mark& mark, YAML::anchor_t anchor, std::size_t bytes) {
    const Size s{1, bytes};
    add(mark, s);
    if (anchor != YAML::NullAnchor) anchors_[anchor] = s;
  }
  void open(const YAML::Mark& mark, YAML::anchor_t anchor) {
    const Size before = total_;
    add(mark, Size{1, 0});
    open_.push_back(Open{anchor, before});
  }
  void close() {
    if (open_.empty()) return;
    const Open o = open_.back();
    open_.pop_back();
    if (o.anchor != YAML::NullAnchor) {
      anchors_[o.anchor] = Size{total_.nodes - o.before.nodes, total_.bytes - o.before.bytes};
    }
  }

  Size total_;
  std::vector<Open> open_;
  std::map<YAML::anchor_t, Size> anchors_;
};

SourceMark mark_in(const std::string& file, bool from_command_line, const YAML::Mark& m) {
  if (from_command_line || m.line < 0) return SourceMark{file, 0, 0};
  return SourceMark{file, m.line + 1, m.column + 1};
}

}  // namespace

YAML::Node load_one_yaml_document(const std::string& text, const std::string& file, bool from_command_line) {
  const SourceMark start = from_command_line ? SourceMark{file, 0, 0} : SourceMark{file, 1, 1};
  if (text.size() > kMaxInputBytes) {
    throw InputError(start, "",
                     "the input is " + std::to_string(text.size()) + " bytes; at most " +
                         std::to_string(kMaxInputBytes) +
                         " bytes (1 MiB) are accepted, a problem or study file is a few kB (docs/input_limits.md)");
  }
  try {
    // Pass 1, streaming: at most two documents (a ',' outside a flow
    // collection makes yaml-cpp report empty documents without end), sizes
    // after alias expansion. Nothing is built, so nothing can blow up.
    {
      std::istringstream in(text);
      YAML::Parser parser(in);
      ExpansionCounter counter;
      while (counter.documents < 2 && parser.HandleNextDocument(counter)) {
      }
      if (counter.documents >= 2) {
        const YAML::Mark& m = counter.second_document;
        const bool stray_comma = m.pos >= 0 && static_cast<std::size_t>(m.pos) < text.size() && text[m.pos] == ',';
        if (stray_comma) {
          throw InputError(mark_in(file, from_command_line, m), "",
                           "a ',' outside a [list] or {map} starts no value (a comment that lost its '#'? a "
                           "value that is only ','?); remove it, or quote a text that contains it ('a, b')");
        }
        throw InputError(mark_in(file, from_command_line, m), "",
                         "more than one YAML document ('---'); a problem or study file holds exactly one");
      }
    }
    // Pass 2: the one document, within the limits just checked.
    return YAML::Load(text);
  } catch (const LimitExceeded& e) {
    throw InputError(mark_in(file, from_command_line, e.mark), "", e.message);
  } catch (const YAML::DeepRecursion& e) {
    // yaml-cpp's own message for this reads "bad file": say what happened.
    throw InputError(mark_in(file, from_command_line, e.mark), "",
                     "nesting deeper than " + std::to_string(e.depth()) + " levels (yaml-cpp's limit)");
  } catch (const YAML::Exception& e) {
    throw InputError(mark_in(file, from_command_line, e.mark), "", "YAML syntax error: " + e.msg);
  }
}

}  // namespace rackopt
