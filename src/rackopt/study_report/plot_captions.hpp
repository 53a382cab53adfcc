// What each plot of a study shows and what to read from it: the title under
// which the report embeds it and the one-line caption printed below it.
#pragma once

#include <string>

#include "rackopt/study/study_spec.hpp"

namespace rackopt::study_report {

struct PlotCaption {
  std::string title;    // "Stiffness over one span" (the image's alt text)
  std::string caption;  // one sentence or two: what to read, and what is physics rather than a fault
};

// The caption of the plot a study's file set lists under `role`
// ("stiffness_png", "history_png", "pareto_png", ...). A role without a
// caption of its own gets its file role as title and no caption.
PlotCaption plot_caption(const std::string& role, const study::StudySpec& spec);

}  // namespace rackopt::study_report
