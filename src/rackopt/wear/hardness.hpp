// Flank hardness versus depth below the original surface (docs/models/wear.md).
//
// Measured data (a polynomial fit or a table) is trusted only where it was
// measured: beyond that, or wherever the data falls below the core hardness,
// the hardness is clamped to the core value and the point is flagged so that
// the caller can warn once. Hardness is never extrapolated to zero or below
// (the wear paper's cubic reaches 0 HB at 11.6 mm, docs/models/wear.md).
#pragma once

#include <string>
#include <vector>

#include "rackopt/core/drive.hpp"

namespace rackopt {

class HardnessModel {
 public:
  struct Value {
    double hardness = 0;        // [Pa], always > 0
    bool outside_data = false;  // clamped: beyond the measured range or below the core
  };

  // Validates `profile` and precomputes what the kinds need. `key` is the
  // dotted key path used in error messages (e.g. "wear.rack_hardness").
  // Throws InputError (key path + limit) for
  //   constant:      surface <= 0 or not finite;
  //   polynomial:    no coefficients, non-finite coefficients, valid_depth <= 0,
  //                  core < 0, or no positive core (core 0 and the fit <= 0 at
  //                  valid_depth);
  //   table:         empty, sizes differ, depths not strictly ascending or < 0,
  //                  values <= 0, core < 0;
  //   case_hardened: surface, core or case_depth <= 0, core >= surface,
  //                  limit (0 = 0.8 surface, ISO 18203 SHD) not strictly between
  //                  core and surface, exponent <= 0.
  explicit HardnessModel(const HardnessProfile& profile, std::string key = "wear.hardness");

  // H at `depth` [m] below the original surface (depth < 0 is read as 0).
  //  constant:      surface;
  //  polynomial:    max(sum c_i h^i, core) for h <= valid_depth, core beyond;
  //  table:         linear between points, the first value above the first depth
  //                 (not flagged: the surface region is what was measured),
  //                 max(., core), core beyond the last depth;
  //  case_hardened: H_c + (H_s - H_c) exp(-(h/delta)^n),
  //                 delta = D_eff / [ln((H_s - H_c)/(H_lim - H_c))]^(1/n),
  //                 so H(D_eff) = H_lim exactly (docs/models/wear.md). Never flagged.
  Value evaluate(double depth) const;
  double operator()(double depth) const { return evaluate(depth).hardness; }

  // Smallest depth [m] at which the value is clamped (infinity if never):
  // wear deeper than this has used hardness that was not measured.
  double first_clamped_depth() const { return first_clamped_depth_; }
  double surface() const { return evaluate(0.0).hardness; }
  double core() const { return core_; }  // after the "0 = last measured value" rule
  // The case-hardening depth D_eff for kCaseHardened; profile.case_depth for
  // the other kinds (0 when not given).
  double case_depth() const { return case_depth_; }
  // delta of the case-hardened form [m] (0 for other kinds).
  double decay_length() const { return delta_; }
  HardnessProfile::Kind kind() const { return kind_; }

 private:
  double polynomial(double h) const;
  double raw_table(double h) const;

  HardnessProfile::Kind kind_;
  double surface_ = 0, core_ = 0, valid_depth_ = 0, case_depth_ = 0;
  double delta_ = 0, exponent_ = 0;
  std::vector<double> coefficients_, depths_, values_;
  double first_clamped_depth_ = 0;
};

}  // namespace rackopt
