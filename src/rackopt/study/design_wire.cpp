#include "rackopt/study/design_wire.hpp"

#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace rackopt::study {

namespace {

class Writer {
 public:
  void count(std::uint64_t n) { raw(&n, sizeof n); }
  void number(double v) { raw(&v, sizeof v); }
  void numbers(const std::vector<double>& v) {
    count(v.size());
    for (double x : v) number(x);
  }
  void text(const std::string& s) {
    count(s.size());
    out_.append(s);
  }
  std::string take() { return std::move(out_); }

 private:
  void raw(const void* p, std::size_t n) { out_.append(static_cast<const char*>(p), n); }
  std::string out_;
};

class Reader {
 public:
  explicit Reader(std::string_view in) : in_(in) {}
  std::uint64_t count() {
    std::uint64_t n = 0;
    raw(&n, sizeof n);
    // No count can exceed the bytes left: a corrupt count ends here, not in
    // a huge allocation.
    if (n > in_.size() - at_) throw std::runtime_error("design wire: a count beyond the message");
    return n;
  }
  double number() {
    double v = 0;
    raw(&v, sizeof v);
    return v;
  }
  std::vector<double> numbers() {
    std::vector<double> v(count());
    for (double& x : v) x = number();
    return v;
  }
  std::string text() {
    const std::uint64_t n = count();
    need(n);
    std::string s(in_.substr(at_, n));
    at_ += n;
    return s;
  }
  bool done() const { return at_ == in_.size(); }

 private:
  void need(std::size_t n) const {
    if (in_.size() - at_ < n) throw std::runtime_error("design wire: message ends early");
  }
  void raw(void* p, std::size_t n) {
    need(n);
    std::memcpy(p, in_.data() + at_, n);
    at_ += n;
  }
  std::string_view in_;
  std::size_t at_ = 0;
};

}  // namespace

std::string encode_designs(const std::vector<std::vector<double>>& xs) {
  Writer w;
  w.count(xs.size());
  for (const auto& x : xs) w.numbers(x);
  return w.take();
}

std::vector<std::vector<double>> decode_designs(std::string_view bytes) {
  Reader r(bytes);
  std::vector<std::vector<double>> xs(r.count());
  for (auto& x : xs) x = r.numbers();
  if (!r.done()) throw std::runtime_error("design wire: bytes after the designs");
  return xs;
}

std::string encode_metrics(const std::vector<DesignMetrics>& results) {
  Writer w;
  w.count(results.size());
  for (const DesignMetrics& m : results) {
    w.numbers(m.x);
    w.numbers(m.metric_values);
    w.count(m.metric_ok.size());
    for (bool ok : m.metric_ok) w.count(ok ? 1 : 0);
    w.text(m.failure);
    w.count(m.warnings.size());
    for (const std::string& warning : m.warnings) w.text(warning);
    w.count(m.models.size());
    for (const std::string& model : m.models) w.text(model);
    w.number(m.seconds);
  }
  return w.take();
}

std::vector<DesignMetrics> decode_metrics(std::string_view bytes) {
  Reader r(bytes);
  std::vector<DesignMetrics> out(r.count());
  for (DesignMetrics& m : out) {
    m.x = r.numbers();
    m.metric_values = r.numbers();
    m.metric_ok.resize(r.count());
    for (std::size_t i = 0; i < m.metric_ok.size(); ++i) m.metric_ok[i] = r.count() != 0;
    m.failure = r.text();
    m.warnings.resize(r.count());
    for (std::string& warning : m.warnings) warning = r.text();
    m.models.resize(r.count());
    for (std::string& model : m.models) model = r.text();
    m.seconds = r.number();
  }
  if (!r.done()) throw std::runtime_error("design wire: bytes after the results");
  return out;
}

std::string encode_sample_lives(const SampleLivesMessage& message) {
  Writer w;
  w.text(message.failure);
  const SampleLives& s = message.lives;
  w.count(s.lives.size());
  for (const statistics::SampleResult& r : s.lives) {
    w.count(static_cast<std::uint64_t>(r.status));
    w.number(r.value);
    w.text(r.code);
    w.text(r.message);
  }
  w.count(s.criteria.size());
  for (const std::string& c : s.criteria) w.text(c);
  w.number(static_cast<double>(s.interpolated));  // a count the message need not be as long as
  return w.take();
}

SampleLivesMessage decode_sample_lives(std::string_view bytes) {
  Reader r(bytes);
  SampleLivesMessage m;
  m.failure = r.text();
  SampleLives& s = m.lives;
  s.lives.resize(r.count());
  for (statistics::SampleResult& life : s.lives) {
    const std::uint64_t status = r.count();
    if (status > static_cast<std::uint64_t>(statistics::SampleResult::Status::kFailed))
      throw std::runtime_error("design wire: an unknown sample status");
    life.status = static_cast<statistics::SampleResult::Status>(status);
    life.value = r.number();
    life.code = r.text();
    life.message = r.text();
  }
  s.criteria.resize(r.count());
  for (std::string& c : s.criteria) c = r.text();
  s.interpolated = static_cast<std::size_t>(r.number());
  if (!r.done()) throw std::runtime_error("design wire: bytes after the sample lives");
  return m;
}

}  // namespace rackopt::study
