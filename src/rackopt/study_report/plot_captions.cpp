#include "rackopt/study_report/plot_captions.hpp"

namespace rackopt::study_report {

PlotCaption plot_caption(const std::string& role, const study::StudySpec& spec) {
  if (role == "stiffness_png") {
    return {"Stiffness over one span",
            "Mesh stiffness, load shares and static transmission error of the best design while the pitch point "
            "travels from one rack support (hinge, dashed) to the next; the jumps are tooth pairs entering and "
            "leaving mesh. The curve is not symmetric about mid-span, and should not be: the tooth force is "
            "inclined and acts above the rack's neutral axis, so its couple adds to the bending deflection on one "
            "half of the span and takes from it on the other (docs/models/rack_span.md)."};
  }
  if (role == "history_png") {
    if (spec.kind == study::StudyKind::kPareto) {
      return {"Front quality against evaluations",
              "Hypervolume of the front found so far (reference point in summary.json): it rises while new "
              "designs extend or fill the front and flattens once more evaluations stop adding to it."};
    }
    return {"Convergence",
            "The best feasible objective found so far against evaluations: a long flat tail means more budget "
            "would not have helped this run; steps late in the run mean it might."};
  }
  if (role == "pareto_png") {
    return {"Pareto front",
            "Each panel projects the front onto two objectives (grey: every evaluation, blue: the front, red "
            "ring: the chosen design). A front point may look dominated in one projection: it is better in an "
            "objective that panel does not show."};
  }
  if (role == "sweep_png") {
    return {"Sweep", "Each metric against the swept variables: read the trends, and where a constraint cuts the "
                     "range."};
  }
  if (role == "fe_png") {
    return {"Analytic model against finite elements",
            "Mesh stiffness of the best design at the same travel positions by the analytic model and by FE: "
            "the gap is the analytic model's error on this design."};
  }
  if (role == "wear_profile_png") {
    return {"Wear along the flanks",
            "Wear depth along the pinion and rack flanks: the life ends when the first point reaches its limit "
            "depth, unless a contact-ratio criterion ends it earlier (docs/models/wear.md)."};
  }
  if (role == "life_histogram_png") {
    return {"Life distribution",
            "Monte Carlo wear lives with the fitted distribution: where the histogram and the fit part, the "
            "fitted life at R is less trustworthy than the empirical one."};
  }
  if (role == "reliability_png") {
    return {"Reliability against time",
            "The probability that the flanks are not yet worn out against time: the life at a reliability R "
            "is where the curve falls through R."};
  }
  return {role, ""};
}

}  // namespace rackopt::study_report
