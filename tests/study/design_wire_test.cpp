// Designs and metrics through bytes and back, bit for bit.
#include "rackopt/study/design_wire.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace rackopt::study {
namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(DesignWire, DesignsRoundTripBitForBit) {
  const std::vector<std::vector<double>> xs{
      {0.1, -0.0, std::numeric_limits<double>::quiet_NaN()}, {}, {1e-300, std::numeric_limits<double>::infinity()}};
  const auto back = decode_designs(encode_designs(xs));
  ASSERT_EQ(back.size(), xs.size());
  for (std::size_t k = 0; k < xs.size(); ++k) {
    ASSERT_EQ(back[k].size(), xs[k].size());
    for (std::size_t i = 0; i < xs[k].size(); ++i) EXPECT_TRUE(same_bits(back[k][i], xs[k][i]));
  }
}

TEST(DesignWire, MetricsRoundTripWithTextsAndFlags) {
  DesignMetrics a;
  a.x = {0.063, 1.25};
  a.metric_values = {1.5e9, 0.0, 0.8123456789012345};
  a.metric_ok = {true, false, true};
  a.failure = "wear_life failed (x): \"quoted\", comma, newline\nand UTF-8 µm";
  a.warnings = {"rack foundation: outside", ""};
  a.models = {"geometry", "stiffness_curve"};
  a.seconds = 0.004;
  DesignMetrics b;  // everything empty
  const auto back = decode_metrics(encode_metrics({a, b}));
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].x, a.x);
  for (std::size_t i = 0; i < a.metric_values.size(); ++i)
    EXPECT_TRUE(same_bits(back[0].metric_values[i], a.metric_values[i]));
  EXPECT_EQ(back[0].metric_ok, a.metric_ok);
  EXPECT_EQ(back[0].failure, a.failure);
  EXPECT_EQ(back[0].warnings, a.warnings);
  EXPECT_EQ(back[0].models, a.models);
  EXPECT_EQ(back[0].seconds, a.seconds);
  EXPECT_TRUE(back[1].x.empty());
  EXPECT_TRUE(back[1].failure.empty());
}

TEST(DesignWire, SampleLivesRoundTripWithFailuresAndCriteria) {
  SampleLivesMessage m;
  statistics::SampleResult ok, bad;
  ok.status = statistics::SampleResult::Status::kOk;
  ok.value = 1.2345678901234567e9;
  bad.status = statistics::SampleResult::Status::kDesignError;
  bad.code = "sample_outside_domain";
  bad.message = "sampled load -3 N: not a drive";
  m.lives.lives = {ok, bad, ok};
  m.lives.criteria = {"max_depth", "", "contact_ratio"};
  m.lives.interpolated = 123456;
  const SampleLivesMessage back = decode_sample_lives(encode_sample_lives(m));
  EXPECT_TRUE(back.failure.empty());
  ASSERT_EQ(back.lives.lives.size(), 3u);
  EXPECT_EQ(back.lives.lives[0].value, ok.value);
  EXPECT_EQ(back.lives.lives[1].status, statistics::SampleResult::Status::kDesignError);
  EXPECT_EQ(back.lives.lives[1].code, bad.code);
  EXPECT_EQ(back.lives.lives[1].message, bad.message);
  EXPECT_EQ(back.lives.criteria, m.lives.criteria);
  EXPECT_EQ(back.lives.interpolated, 123456u);
  SampleLivesMessage failed;
  failed.failure = "the design has no random inputs to sample";
  EXPECT_EQ(decode_sample_lives(encode_sample_lives(failed)).failure, failed.failure);
  const std::string bytes = encode_sample_lives(m);
  EXPECT_THROW(decode_sample_lives(bytes.substr(0, bytes.size() - 3)), std::runtime_error);
}

TEST(DesignWire, TruncatedOrPaddedBytesAreRefused) {
  DesignMetrics a;
  a.x = {1, 2};
  a.failure = "why";
  const std::string bytes = encode_metrics({a});
  for (std::size_t cut : {std::size_t{0}, std::size_t{7}, bytes.size() - 1})
    EXPECT_THROW(decode_metrics(std::string_view(bytes).substr(0, cut)), std::runtime_error) << cut;
  EXPECT_THROW(decode_metrics(bytes + "x"), std::runtime_error);
  std::string huge = bytes;
  huge[0] = '\x7f';  // an absurd design count
  huge[7] = '\x7f';
  EXPECT_THROW(decode_metrics(huge), std::runtime_error);
}

}  // namespace
}  // namespace rackopt::study
