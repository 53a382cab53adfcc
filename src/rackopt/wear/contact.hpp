// Contact conditions along the rack-pinion path of contact for Archard wear:
// Hertz line contact (docs/models/wear.md), rolling and sliding speeds
// (7.4) and the wear of one pass (10.2).
//
// LOA coordinate s is measured from the pinion base-circle tangency point T
// (mesh_geometry.hpp); the pitch point is at s_P = r sin a0.
#pragma once

namespace rackopt {

// Line contact of width b under a load per unit width w = F/b [N/m] between a
// cylinder of radius R' and a plane (the rack flank is flat, so R' = s):
//   a = sqrt(4 w R'/(pi E*)),  p0 = 2 w/(pi a),  p_mean = pi p0/4 = w/(2a)
// (Johnson 1985, Contact Mechanics, ch. 4). w = 0 gives zeros.
// Throws InputError for w < 0, R' <= 0 or E* <= 0 (or non-finite values).
struct HertzLineContact {
  double half_width = 0;     // a [m]
  double peak_pressure = 0;  // p0 [Pa]
  double mean_pressure = 0;  // p_mean over the band [Pa]
};
HertzLineContact hertz_line_contact(double load_per_width, double effective_radius, double e_star);

// Rolling and sliding of the contact at LOA coordinate s, per unit pinion
// angular speed (docs/models/wear.md): pinion rolling speed v1 = s (involute
// curvature radius), rack rolling speed v2 = s_P (constant), sliding
// |v1 - v2| = |s - s_P|.
//
// The pinion point near the base circle rolls infinitely slowly (v1 -> 0 as
// s -> 0), which would make its wear per pass infinite. Such contacts only
// exist with interference ignored; the pinion rolling speed is floored at
// `min_pinion_rolling` [m] (the caller uses 1e-3 r_b).
class RackPinionSliding {
 public:
  // Throws InputError for s_pitch <= 0 or min_pinion_rolling <= 0.
  RackPinionSliding(double s_pitch, double min_pinion_rolling);

  double pinion_rolling(double s) const;  // max(s, floor) [m per rad]
  double rack_rolling() const { return s_pitch_; }
  double sliding(double s) const;  // |s - s_P|
  // Sliding distance per unit rolling distance of each member's surface point:
  // |v1 - v2|/v_i. The wear per pass at a flank point is k w times this.
  double pinion_sliding_ratio(double s) const { return sliding(s) / pinion_rolling(s); }
  double rack_sliding_ratio(double s) const { return sliding(s) / s_pitch_; }
  // Signed specific sliding (docs/models/wear.md): zeta1 = 1 - s_P/s, zeta2 = 1 - s/s_P.
  double pinion_specific_sliding(double s) const { return 1.0 - s_pitch_ / pinion_rolling(s); }
  double rack_specific_sliding(double s) const { return 1.0 - s / s_pitch_; }

 private:
  double s_pitch_, floor_;
};

// Archard wear depth of one pass of a flank point through a contact band
// (Flodin & Andersson 1997; docs/models/wear.md):
//   dh = k w |v1 - v2|/v_i = k p_mean s_i,  s_i = 2 a |v1 - v2|/v_i,
// with k = K/H [m^2/N]. Not p0: that over-predicts by 4/pi.
inline double archard_pass_wear(double k, double load_per_width, double sliding_ratio) {
  return k * load_per_width * sliding_ratio;
}

}  // namespace rackopt
