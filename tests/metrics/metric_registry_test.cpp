// Metric registry: lookup, error messages, the request text form.
#include "rackopt/metrics/metric_registry.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "rackopt/core/error.hpp"

namespace rackopt::metrics {
namespace {

std::string error_of(const std::string& text) {
  try {
    parse_metric_request(text);
  } catch (const InputError& e) {
    EXPECT_EQ(e.key_path(), "metric");
    return e.message();
  }
  ADD_FAILURE() << "no InputError for '" << text << "'";
  return {};
}

TEST(MetricRegistry, EveryBriefMetricIsThereOnceWithUnitAndModels) {
  std::set<std::string> names;
  for (const MetricDefinition& d : metric_registry()) {
    EXPECT_TRUE(names.insert(std::string(d.name)).second) << d.name;
    EXPECT_FALSE(d.unit.empty()) << d.name;
    EXPECT_FALSE(d.description.empty()) << d.name;
    EXPECT_FALSE(d.source.empty()) << d.name;
  }
  for (const char* n : {"stiffness_fluctuation", "min_stiffness", "max_stiffness", "mean_stiffness",
                        "min_stiffness_ks", "max_stiffness_ks", "stiffness_fluctuation_ks", "contact_ratio",
                        "wear_life", "wear_life_at_R", "supports_per_metre", "root_bending_stress",
                        "root_bending_safety", "contact_stress", "contact_safety"}) {
    EXPECT_TRUE(names.count(n)) << n;
  }
  EXPECT_EQ(find_metric("contact_ratio").models, (ModelSet{Model::kGeometry}));
  EXPECT_EQ(find_metric("min_stiffness").models, (ModelSet{Model::kStiffnessCurve}));
  EXPECT_TRUE(find_metric("supports_per_metre").models.empty());
  EXPECT_EQ(find_metric("min_stiffness").unit, "N/m");
  EXPECT_EQ(find_metric("wear_life").unit, "s");
  EXPECT_TRUE(find_metric("min_stiffness_ks").smooth);
  EXPECT_FALSE(find_metric("min_stiffness").smooth);
  EXPECT_EQ((ModelSet{Model::kStress, Model::kGeometry}).names(), (std::vector<std::string>{"geometry", "stress"}));
}

TEST(MetricRegistry, UnknownNameListsValidNamesAndSuggestsTheNearest) {
  const std::string typo = error_of("contact_ratoi");
  EXPECT_NE(typo.find("did you mean 'contact_ratio'"), std::string::npos) << typo;
  EXPECT_NE(typo.find("wear_life_at_R"), std::string::npos) << typo;  // the list of valid names
  EXPECT_NE(error_of("min_stifness").find("did you mean 'min_stiffness'"), std::string::npos);
  const std::string far = error_of("efficiency");
  EXPECT_EQ(far.find("did you mean"), std::string::npos) << far;
  EXPECT_NE(far.find("supports_per_metre"), std::string::npos) << far;
}

TEST(MetricRegistry, ParsesTheTextFormAndChecksTheParameter) {
  const MetricRequest a = parse_metric_request("wear_life_at_R(0.9)");
  EXPECT_EQ(a.name, "wear_life_at_R");
  ASSERT_TRUE(a.parameter);
  EXPECT_EQ(*a.parameter, 0.9);
  const MetricRequest b = parse_metric_request("  min_stiffness_ks ( 50 ) ");
  EXPECT_EQ(b.name, "min_stiffness_ks");
  EXPECT_EQ(*b.parameter, 50.0);
  const MetricRequest c = parse_metric_request("contact_ratio");
  EXPECT_FALSE(c.parameter);

  EXPECT_NE(error_of("contact_ratio(2)").find("takes no parameter"), std::string::npos);
  EXPECT_NE(error_of("wear_life_at_R").find("needs its parameter R"), std::string::npos);
  EXPECT_NE(error_of("wear_life_at_R(1)").find("strictly between 0 and 1"), std::string::npos);
  EXPECT_NE(error_of("wear_life_at_R(0)").find("strictly between"), std::string::npos);
  EXPECT_NE(error_of("wear_life_at_R(x)").find("not a number"), std::string::npos);
  EXPECT_NE(error_of("wear_life_at_R(0.9").find("name(number)"), std::string::npos);
  EXPECT_NE(error_of("min_stiffness_ks(-1)").find("strictly between"), std::string::npos);
  EXPECT_NE(error_of("(0.5)").find("no metric name"), std::string::npos);
}

TEST(MetricRegistry, DefaultParameterAndLabelsRoundTrip) {
  const MetricRequest r = resolve_request({"min_stiffness_ks", std::nullopt});
  ASSERT_TRUE(r.parameter);
  EXPECT_EQ(*r.parameter, find_metric("min_stiffness_ks").parameter.default_value);
  EXPECT_EQ(to_string(MetricRequest{"contact_ratio", std::nullopt}), "contact_ratio");
  for (double R : {0.9, 0.95, 0.999, 0.1 + 0.2}) {
    const MetricRequest q{"wear_life_at_R", R};
    const MetricRequest back = parse_metric_request(to_string(q));
    EXPECT_EQ(*back.parameter, R) << to_string(q);  // shortest round-trip text
  }
  EXPECT_EQ(to_string(MetricRequest{"wear_life_at_R", 0.9}), "wear_life_at_R(0.9)");
}

}  // namespace
}  // namespace rackopt::metrics
