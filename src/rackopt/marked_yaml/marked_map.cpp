#include "rackopt/marked_yaml/marked_map.hpp"

#include <algorithm>
#include <cctype>

#include "rackopt/core/suggest.hpp"
#include "rackopt/core/text.hpp"

namespace rackopt {


MarkedMap::MarkedMap(const MarkedNode* node, std::string path, const SourceMark& fallback,
                     std::vector<std::string> allowed, const std::string& example, NameSuggester suggest)
    : node_(node), path_(std::move(path)), mark_(fallback), allowed_(std::move(allowed)) {
  if (node_ != nullptr && node_->is_null()) node_ = nullptr;
  if (node_ == nullptr) return;
  mark_ = node_->mark;
  if (!node_->is_map()) {
    throw InputError(node_->mark, path_,
                     "expected a map of keys (" + join(allowed_) + ")" +
                         (example.empty() ? "" : ", e.g. " + example) + ", found " + node_->type_name());
  }
  if (allowed_.empty()) return;
  if (suggest == nullptr) suggest = closest_name;
  for (const auto& e : node_->entries) {
    if (std::find(allowed_.begin(), allowed_.end(), e.key) != allowed_.end()) continue;
    std::string message = "unknown key '" + e.key + "'";
    message += path_.empty() ? " at the top level" : " in " + path_;
    if (const auto best = suggest(e.key, allowed_)) message += "; did you mean '" + *best + "'?";
    message += " Allowed keys: " + join(allowed_);
    throw InputError(e.key_mark, child_path(e.key), message);
  }
}

const MarkedNode* MarkedMap::get(const std::string& key) const {
  if (node_ == nullptr) return nullptr;
  const MarkedNode* v = node_->find(key);
  return (v == nullptr || v->is_null()) ? nullptr : v;
}

SourceMark MarkedMap::key_mark(const std::string& key) const {
  if (node_ != nullptr) {
    for (const auto& e : node_->entries) {
      if (e.key == key) return e.key_mark;
    }
  }
  return mark_;
}

SourceMark MarkedMap::value_mark(const std::string& key) const {
  if (const MarkedNode* v = get(key)) return v->mark;
  return key_mark(key);
}

void MarkedMap::missing(const std::string& key, const std::string& expected) const {
  throw InputError(mark_, child_path(key), "required key '" + key + "' is missing; expected " + expected);
}

std::optional<std::pair<std::string, SourceMark>> MarkedMap::scalar(const std::string& key,
                                                                     const std::string& expected) const {
  const MarkedNode* v = get(key);
  if (v == nullptr) return std::nullopt;
  if (v->type != MarkedNode::Type::kScalar) {
    throw InputError(v->mark, child_path(key), "expected " + expected + ", found " + v->type_name());
  }
  return std::make_pair(v->scalar, v->mark);
}

std::string MarkedMap::text(const std::string& key, const std::string& fallback) const {
  const auto t = scalar(key, "a text");
  return t ? t->first : fallback;
}

bool MarkedMap::flag(const std::string& key, bool fallback) const {
  const auto t = scalar(key, "on or off");
  if (!t) return fallback;
  std::string v = t->first;
  for (auto& c : v) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (v == "on" || v == "true" || v == "yes") return true;
  if (v == "off" || v == "false" || v == "no") return false;
  throw InputError(t->second, child_path(key), "'" + t->first + "' is not a switch; allowed: on, off (or true, false)");
}

}  // namespace rackopt
