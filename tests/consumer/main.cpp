// Built against the installed package: loads a problem, computes the
// stiffness curve and two metrics by name, and prints them.
#include <rackopt/rackopt.hpp>

#include <cstdio>
#include <exception>
#include <vector>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: consumer PROBLEM.yaml\n");
    return 2;
  }
  try {
    const rackopt::Drive drive = rackopt::load_problem(argv[1]);
    const rackopt::StiffnessCurve curve = rackopt::MeshStiffnessModel(drive).curve();
    const std::vector<rackopt::metrics::MetricRequest> want{rackopt::metrics::parse_metric_request("contact_ratio"),
                                                            rackopt::metrics::parse_metric_request("min_stiffness")};
    const rackopt::metrics::MetricValues v = rackopt::metrics::evaluate_metrics(drive, want, {});
    if (!v.all_ok()) return 1;
    std::printf("rackopt %s\nk_min %.9g\nk_mean %.9g\ncontact_ratio %.9g\nmin_stiffness %.9g\n",
                RACKOPT_VERSION_STRING, curve.k_min, curve.k_mean, v.values[0].value, v.values[1].value);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 1;
  }
}
