// Plot scripts carry user text (problem and study names) inside gnuplot
// strings: a name with an apostrophe must stay one string. Drawing them is
// covered end to end by the CLI tests (the shipped rack railway's name has
// an apostrophe).
#include <gtest/gtest.h>

#include <string>

#include "rackopt/output/plot.hpp"
#include "rackopt/output/stiffness_report.hpp"
#include "rackopt/output/wear_report.hpp"

namespace rackopt {
namespace {

TEST(PlotScripts, GnuplotQuoteDoublesTheQuote) {
  EXPECT_EQ(gnuplot_quote("plain"), "'plain'");
  EXPECT_EQ(gnuplot_quote("the paper's drive"), "'the paper''s drive'");
  EXPECT_EQ(gnuplot_quote("''"), "''''''");
  EXPECT_EQ(gnuplot_quote(""), "''");
}

TEST(PlotScripts, TitlesWithAnApostropheStayOneString) {
  const std::string name = "Mountain rack railway (the paper's drive)";
  // The scripts may add to the title: the quoted name without its closing quote.
  const std::string quoted = gnuplot_quote(name);
  const std::string opening = quoted.substr(0, quoted.size() - 1);
  for (const std::string& script : {wear_profile_gnuplot(name), life_histogram_gnuplot(name),
                                    reliability_gnuplot(name), stiffness_gnuplot(StiffnessCurve{}, name, "s.csv", "s.png")}) {
    EXPECT_NE(script.find(opening), std::string::npos) << script.substr(0, 400);
    EXPECT_EQ(script.find("paper's"), std::string::npos) << "the raw name, unescaped";
  }
}

}  // namespace
}  // namespace rackopt
