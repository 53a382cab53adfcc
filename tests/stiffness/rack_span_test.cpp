// Rack body on two hinges (rack_span.hpp, docs/models/rack_span.md).
//
// Expected numbers come from:
//  * docs/models/rack_span.md: the single-load closed form (plus the Timoshenko couple
//    term c^2 e^2/(l kGA) derived in docs/models/rack_span.md) and the k_body
//    table (50.7 / 24.0 / 24.5 / 90.0 / 329 MN/m);
//  * an independent Timoshenko beam finite-element model written here
//    (two-node elements with the exact Timoshenko stiffness, axial bars,
//    hinges as boundary conditions, statically equivalent nodal loads);
//  * properties: Maxwell-Betti symmetry, positive definiteness, continuity,
//    scaling with EI, limits.
#include "rackopt/stiffness/rack_span.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace {

using rackopt::Effects;
using rackopt::RackSpanCompliance;
using rackopt::RackSpec;
using rackopt::Supports;

const double kAlpha14 = 14.0 * std::numbers::pi / 180.0;

// Rectangular body b x h of steel (E = 210 GPa, nu = 0.3), kappa = 1/1.2.
RackSpec rectangular_rack(double span, double width, double height, Supports supports) {
  RackSpec rack;
  rack.span = span;
  rack.supports = supports;
  rack.material.youngs_modulus = 210e9;
  rack.material.poisson_ratio = 0.3;
  rack.section.area = width * height;
  rack.section.second_moment = width * height * height * height / 12.0;
  rack.section.shear_area = width * height / 1.2;
  rack.section.neutral_axis_depth = height / 2.0;
  return rack;
}

// The rack railway paper's / docs/models/rack_span.md body: 60 x 75.5 mm, l = 2.4 m.
RackSpec seed_rack(Supports supports = Supports::kPinPin) {
  return rectangular_rack(2.4, 0.060, 0.0755, supports);
}

Effects all_effects() {
  Effects fx;
  fx.couple_term = true;
  fx.body_axial = true;
  fx.body_shear = true;
  return fx;
}

// ---------------------------------------------------------------------------
// Independent Timoshenko beam FE. Node i at x = i l / n, DOFs (u, v, psi).
// Bending element (Przemieniecki; phi = 12 EI/(kGA h^2)):
//   EI/((1+phi) h^3) [12, 6h, -12, 6h; 6h, (4+phi)h^2, -6h, (2-phi)h^2; ...]
// which is exact for nodal loads on a prismatic Timoshenko beam (psi is the
// section rotation). Axial: EA/h [1, -1; -1, 1].
class TimoshenkoFe {
 public:
  TimoshenkoFe(const RackSpec& rack, double alpha, const Effects& fx, int elements)
      : n_(elements), l_(rack.span), s_(std::sin(alpha)), c_(std::cos(alpha)), couple_(fx.couple_term) {
    const double E = rack.material.youngs_modulus;
    const double G = E / (2.0 * (1.0 + rack.material.poisson_ratio));
    const double EI = E * rack.section.second_moment;
    // Shear off: phi = 0 (Euler-Bernoulli element); axial off: every u fixed.
    const double EA = E * rack.section.area;
    const double h = l_ / n_;
    const double phi = fx.body_shear ? 12.0 * EI / (G * rack.section.shear_area * h * h) : 0.0;

    // Constrained DOFs: u0, v0, vN, and uN for pin-pin.
    const int full = 3 * (n_ + 1);
    index_.assign(full, -1);
    std::vector<bool> fixed(full, false);
    fixed[dof(0, 0)] = fixed[dof(0, 1)] = fixed[dof(n_, 1)] = true;
    if (rack.supports == Supports::kPinPin) fixed[dof(n_, 0)] = true;
    if (!fx.body_axial)
      for (int i = 0; i <= n_; ++i) fixed[dof(i, 0)] = true;
    int m = 0;
    for (int i = 0; i < full; ++i)
      if (!fixed[i]) index_[i] = m++;

    std::vector<Eigen::Triplet<double>> t;
    const double kb = EI / ((1.0 + phi) * h * h * h);
    const double kbend[4][4] = {{12, 6 * h, -12, 6 * h},
                                {6 * h, (4 + phi) * h * h, -6 * h, (2 - phi) * h * h},
                                {-12, -6 * h, 12, -6 * h},
                                {6 * h, (2 - phi) * h * h, -6 * h, (4 + phi) * h * h}};
    for (int e = 0; e < n_; ++e) {
      const int bend[4] = {dof(e, 1), dof(e, 2), dof(e + 1, 1), dof(e + 1, 2)};
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) add(t, bend[i], bend[j], kb * kbend[i][j]);
      const int ax[2] = {dof(e, 0), dof(e + 1, 0)};
      const double ka = EA / h;
      add(t, ax[0], ax[0], ka);
      add(t, ax[1], ax[1], ka);
      add(t, ax[0], ax[1], -ka);
      add(t, ax[1], ax[0], -ka);
    }
    K_.resize(m, m);
    K_.setFromTriplets(t.begin(), t.end());
    solver_.compute(K_);
    if (solver_.info() != Eigen::Success) throw std::runtime_error("FE factorisation failed");
  }

  // LOA displacement at contact j per unit LOA force at contact k (node indices).
  double influence(int node_j, double e_j, int node_k, double e_k) const {
    const double ej = couple_ ? e_j : 0.0, ek = couple_ ? e_k : 0.0;
    Eigen::VectorXd f = Eigen::VectorXd::Zero(K_.rows());
    put(f, dof(node_k, 0), c_);        // axial +cos a0
    put(f, dof(node_k, 1), -s_);       // vertical -sin a0
    put(f, dof(node_k, 2), -ek * c_);  // couple -e cos a0
    const Eigen::VectorXd d = solver_.solve(f);
    const double u = get(d, dof(node_j, 0)), v = get(d, dof(node_j, 1)), psi = get(d, dof(node_j, 2));
    return c_ * (u - ej * psi) - s_ * v;
  }

  double abscissa(int node) const { return node * l_ / n_; }

 private:
  static int dof(int node, int k) { return 3 * node + k; }
  void add(std::vector<Eigen::Triplet<double>>& t, int i, int j, double value) const {
    if (index_[i] >= 0 && index_[j] >= 0) t.emplace_back(index_[i], index_[j], value);
  }
  void put(Eigen::VectorXd& f, int i, double value) const {
    if (index_[i] >= 0) f[index_[i]] += value;  // loads on a fixed DOF go to the support
  }
  double get(const Eigen::VectorXd& d, int i) const { return index_[i] >= 0 ? d[index_[i]] : 0.0; }

  int n_;
  double l_, s_, c_;
  bool couple_;
  std::vector<int> index_;
  Eigen::SparseMatrix<double> K_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver_;
};

struct FeCase {
  const char* name;
  RackSpec rack;
  Effects fx;
  std::vector<int> nodes;     // contact nodes (of 480 elements)
  std::vector<double> heights;  // e at each contact
};

void compare_with_fe(const FeCase& fc, double rel_tol) {
  const int n = 480;
  TimoshenkoFe fe(fc.rack, kAlpha14, fc.fx, n);
  RackSpanCompliance body(fc.rack, kAlpha14, fc.fx);
  const std::size_t m = fc.nodes.size();
  for (std::size_t j = 0; j < m; ++j) {
    for (std::size_t k = 0; k < m; ++k) {
      const double aj = fe.abscissa(fc.nodes[j]), ak = fe.abscissa(fc.nodes[k]);
      const double got = body.influence(aj, fc.heights[j], ak, fc.heights[k]);
      const double want = fe.influence(fc.nodes[j], fc.heights[j], fc.nodes[k], fc.heights[k]);
      // Scale by the diagonal: cross terms can pass through zero.
      const double scale = std::sqrt(body.self(aj, fc.heights[j]) * body.self(ak, fc.heights[k]));
      EXPECT_NEAR(got, want, rel_tol * scale)
          << fc.name << ": a_j = " << aj << ", a_k = " << ak << ", e_j = " << fc.heights[j]
          << ", e_k = " << fc.heights[k];
    }
  }
}

// Nodes of 480 elements: 1 -> 5 mm from the left hinge, 30 -> 0.15 m, 120 ->
// 0.6 m, 240 -> midspan, 450 -> 2.25 m, 479 -> 5 mm from the right hinge, and
// both hinges.
const std::vector<int> kNodes = {0, 1, 30, 120, 240, 241, 360, 450, 479, 480};
const std::vector<double> kHeights = {0.08, 0.07, 0.0817, 0.09, 0.075, 0.06, 0.1, 0.0817, 0.05, 0.085};

}  // namespace

// ---- independent FE --------------------------------------------------------

// Exact elements: agreement is limited by round-off of the FE solve only, so
// a tolerance of 1e-6 (far below the 0.2% asked for) still catches any missing
// term (the smallest one, shear_couple, is about 1e-4 of the total here).
TEST(RackSpanFe, SeedSectionBothSupportsWithAndWithoutShear) {
  for (Supports sup : {Supports::kPinPin, Supports::kPinRoller}) {
    for (bool shear : {true, false}) {
      for (bool axial : {true, false}) {
        Effects fx = all_effects();
        fx.body_shear = shear;
        fx.body_axial = axial;
        compare_with_fe({"seed section", seed_rack(sup), fx, kNodes, kHeights}, 1e-6);
      }
    }
  }
}

TEST(RackSpanFe, WithoutCoupleTerm) {
  Effects fx = all_effects();
  fx.couple_term = false;
  compare_with_fe({"no couple", seed_rack(Supports::kPinPin), fx, kNodes, kHeights}, 1e-6);
  compare_with_fe({"no couple, roller", seed_rack(Supports::kPinRoller), fx, kNodes, kHeights}, 1e-6);
}

// A short, deep body (l = 0.6 m, 60 x 150 mm) where shear matters: here the
// Timoshenko couple term is a few % of the self compliance near a hinge, and
// the FE must see it.
TEST(RackSpanFe, ShortDeepBodyNeedsTheTimoshenkoCoupleTerm) {
  const RackSpec rack = rectangular_rack(0.6, 0.060, 0.150, Supports::kPinPin);
  const Effects fx = all_effects();
  compare_with_fe({"short deep", rack, fx, kNodes, kHeights}, 1e-6);
  compare_with_fe({"short deep roller", rectangular_rack(0.6, 0.060, 0.150, Supports::kPinRoller), fx,
                   kNodes, kHeights},
                  1e-6);

  // Dropping the term (docs/models/rack_span.md as printed) misses the FE by far more
  // than the tolerance near the right hinge.
  TimoshenkoFe fe(rack, kAlpha14, fx, 480);
  RackSpanCompliance body(rack, kAlpha14, fx);
  const double a = fe.abscissa(450), e = 0.12;
  const auto p = body.parts(a, e, a, e);
  const double fe_value = fe.influence(450, e, 450, e);
  EXPECT_GT(std::abs(p.total() - p.shear_couple - fe_value) / fe_value, 0.01);
  EXPECT_NEAR(p.total(), fe_value, 1e-6 * fe_value);
}

// ---- docs/models/rack_span.md closed forms ------------------------------------------

namespace {
// docs/models/rack_span.md single-load compliance, plus the Timoshenko couple term.
double physics_single_load(double a, double e, double l, double EI, double EA, double GA, bool pin_pin,
                           double alpha) {
  const double s = std::sin(alpha), c = std::cos(alpha), b = l - a;
  const double f_ax = pin_pin ? a * b / (EA * l) : a / EA;
  return s * s * a * a * b * b / (3 * EI * l) + c * c * e * e * (a * a * a + b * b * b) / (3 * EI * l * l) +
         2 * s * c * e * a * b * (b - a) / (3 * EI * l) + c * c * f_ax + 1.2 * s * s * a * b / (GA * l) +
         1.2 * c * c * e * e / (GA * l);  // last term: the Timoshenko couple term
}
}  // namespace

TEST(RackSpan, SingleLoadMatchesPhysicsClosedForm) {
  for (Supports sup : {Supports::kPinPin, Supports::kPinRoller}) {
    const RackSpec rack = seed_rack(sup);
    RackSpanCompliance body(rack, kAlpha14, all_effects());
    const double E = 210e9, G = E / 2.6, A = rack.section.area, EI = E * rack.section.second_moment;
    for (double a : {0.0, 0.15, 0.6, 1.2, 1.8, 2.25, 2.4}) {
      for (double e : {0.0, 0.05, 0.0817}) {
        const double want = physics_single_load(a, e, 2.4, EI, E * A, G * A, sup == Supports::kPinPin, kAlpha14);
        EXPECT_NEAR(body.self(a, e), want, 1e-12 * want + 1e-30) << "a = " << a << ", e = " << e;
      }
    }
  }
}

// docs/models/rack_span.md midspan form: s^2 l^3/(48EI) + c^2 e^2 l/(12EI) + c^2 f_ax
// + 1.2 s^2 l/(4GA), plus 1.2 c^2 e^2/(G A l); the coupling term vanishes.
TEST(RackSpan, MidspanMatchesPhysicsClosedForm) {
  const RackSpec rack = seed_rack();
  RackSpanCompliance body(rack, kAlpha14, all_effects());
  const double l = 2.4, e = 0.0817, E = 210e9, G = E / 2.6, A = rack.section.area;
  const double EI = E * rack.section.second_moment;
  const double s = std::sin(kAlpha14), c = std::cos(kAlpha14);
  const double f_ax = (l / 2) * (l / 2) / (E * A * l);
  const double want = s * s * l * l * l / (48 * EI) + c * c * e * e * l / (12 * EI) + c * c * f_ax +
                      1.2 * s * s * l / (4 * G * A) + 1.2 * c * c * e * e / (G * A * l);
  EXPECT_NEAR(body.self(l / 2, e), want, 1e-12 * want);
  EXPECT_NEAR(body.parts(l / 2, e, l / 2, e).coupling, 0.0, 1e-12 * want);
}

// docs/models/rack_span.md table, EI = 4.5e5 N m^2 (h = 75.5 mm), pin-pin, l = 2.4 m,
// 14 deg: k_body = 50.7 / 24.0 / 24.5 / 90.0 / 329 MN/m. The table does not
// state e; one height, e = 81.7 mm above the neutral axis, reproduces all five
// values to 0.11% with the exact 60 x 75.5 mm section (EI = 4.519e5 N m^2,
// A = 4530 mm^2, kappa = 1/1.2, steel). One fitted parameter against five
// numbers: the shape over the span is a genuine check. Tolerance 1%.
TEST(RackSpan, ReproducesPhysicsTable) {
  RackSpanCompliance body(seed_rack(), kAlpha14, all_effects());
  const double e = 0.0817;
  const double a[] = {0.15, 0.6, 1.2, 1.8, 2.25};
  const double k_mn[] = {50.7, 24.0, 24.5, 90.0, 329.0};
  for (int i = 0; i < 5; ++i) {
    const double k = 1.0 / body.self(a[i], e) / 1e6;
    EXPECT_NEAR(k, k_mn[i], 0.01 * k_mn[i]) << "a = " << a[i];
  }
}

// The qualitative claims of docs/models/rack_span.md around the table's e. (The
// "minimum not at midspan" claim needs e above about 78 mm: with the contact
// on the rack datum, e = 37.75 + 33.93 = 71.7 mm, 0.6 m is stiffer than 1.2 m.)
TEST(RackSpan, PhysicsTableProperties) {
  RackSpanCompliance body(seed_rack(), kAlpha14, all_effects());
  for (double e : {0.08, 0.0817, 0.09}) {
    // The minimum is not at midspan: 0.6 m is softer than 1.2 m.
    EXPECT_GT(body.self(0.6, e), body.self(1.2, e)) << e;
    // Asymmetric: the left end (drive force pointing into the span) is much
    // softer than the mirror position at the right end.
    EXPECT_GT(body.self(0.15, e), 3.0 * body.self(2.25, e)) << e;
    // Near a support the couple terms dominate the vertical bending.
    for (double a : {0.15, 2.25}) {
      const auto p = body.parts(a, e, a, e);
      EXPECT_GT(p.couple + std::abs(p.coupling), p.vertical) << a;
    }
  }
}

// ---- properties --------------------------------------------------------------

TEST(RackSpan, ExactlySymmetric) {
  for (Supports sup : {Supports::kPinPin, Supports::kPinRoller}) {
    RackSpanCompliance body(seed_rack(sup), kAlpha14, all_effects());
    const double as[] = {0.0, 0.013, 0.6, 1.2, 1.2, 2.3999, 2.4};
    const double es[] = {0.08, 0.07, 0.0817, 0.09, 0.06, 0.1, 0.05};
    for (int j = 0; j < 7; ++j)
      for (int k = 0; k < 7; ++k)
        EXPECT_EQ(body.influence(as[j], es[j], as[k], es[k]), body.influence(as[k], es[k], as[j], es[j]));
  }
}

TEST(RackSpan, PartsSumToInfluence) {
  RackSpanCompliance body(seed_rack(), kAlpha14, all_effects());
  for (double aj : {0.0, 0.3, 1.7})
    for (double ak : {0.2, 1.7, 2.4})
      EXPECT_EQ(body.parts(aj, 0.08, ak, 0.07).total(), body.influence(aj, 0.08, ak, 0.07));
}

// self() is influence() of a contact on itself written without the
// ordering of two contacts: the same bits for every switch of the body model.
TEST(RackSpan, SelfIsInfluenceOnItselfExactly) {
  for (Supports sup : {Supports::kPinPin, Supports::kPinRoller}) {
    for (int flags = 0; flags < 8; ++flags) {
      Effects fx = all_effects();
      fx.couple_term = (flags & 1) != 0;
      fx.body_shear = (flags & 2) != 0;
      fx.body_axial = (flags & 4) != 0;
      RackSpanCompliance body(seed_rack(sup), kAlpha14, fx);
      for (double a : {0.0, 1e-12, 0.013, 0.6, 1.2, 1.7171, 2.3999, 2.4}) {
        for (double e : {-0.02, 0.0, 0.0817, 0.1}) {
          EXPECT_EQ(body.self(a, e), body.influence(a, e, a, e)) << "a = " << a << ", e = " << e << ", flags " << flags;
        }
      }
    }
  }
}

// Three contacts a pitch (100 mm, the rack railway paper) apart anywhere on the span: the
// 3x3 body flexibility matrix is symmetric positive definite.
TEST(RackSpan, ThreeContactMatrixPositiveDefinite) {
  for (Supports sup : {Supports::kPinPin, Supports::kPinRoller}) {
    for (bool shear : {true, false}) {
      Effects fx = all_effects();
      fx.body_shear = shear;
      RackSpanCompliance body(seed_rack(sup), kAlpha14, fx);
      const double e[3] = {0.07, 0.0817, 0.09};
      for (double a0 = 0.0; a0 <= 2.2 + 1e-9; a0 += 0.05) {
        Eigen::Matrix3d C;
        for (int j = 0; j < 3; ++j)
          for (int k = 0; k < 3; ++k) C(j, k) = body.influence(a0 + 0.1 * j, e[j], a0 + 0.1 * k, e[k]);
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(C);
        EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0) << "a0 = " << a0;
      }
    }
  }
}

// Continuous in a, also where a_j crosses a_k and at the hinges.
TEST(RackSpan, ContinuousInAbscissa) {
  RackSpanCompliance body(seed_rack(), kAlpha14, all_effects());
  const double d = 1e-7;
  for (double ak : {0.0, 0.6, 1.2, 2.4}) {
    const double ref = body.influence(ak, 0.08, ak, 0.07);
    for (double aj : {ak - d, ak + d}) {
      if (aj < 0 || aj > 2.4) continue;
      EXPECT_NEAR(body.influence(aj, 0.08, ak, 0.07), ref, 1e-5 * std::abs(ref)) << aj << " " << ak;
    }
  }
  // The self compliance over the span has no jumps: neighbouring samples
  // 1 mm apart differ by less than 1%.
  double prev = body.self(0.0, 0.08);
  for (int i = 1; i <= 2400; ++i) {
    const double cur = body.self(i * 1e-3, 0.08);
    EXPECT_LT(std::abs(cur - prev), 0.01 * std::max(cur, prev)) << i;
    prev = cur;
  }
}

// Doubling I halves the bending parts and leaves axial and shear unchanged.
TEST(RackSpan, BendingScalesWithInverseEI) {
  RackSpec stiff = seed_rack();
  stiff.section.second_moment *= 2.0;
  RackSpanCompliance base(seed_rack(), kAlpha14, all_effects());
  RackSpanCompliance twice(stiff, kAlpha14, all_effects());
  const auto p = base.parts(0.4, 0.08, 1.9, 0.07);
  const auto q = twice.parts(0.4, 0.08, 1.9, 0.07);
  EXPECT_NEAR(q.vertical, p.vertical / 2, 1e-12 * p.vertical);
  EXPECT_NEAR(q.couple, p.couple / 2, 1e-12 * std::abs(p.couple));
  EXPECT_NEAR(q.coupling, p.coupling / 2, 1e-12 * std::abs(p.coupling));
  EXPECT_EQ(q.axial, p.axial);
  EXPECT_EQ(q.shear, p.shear);
  EXPECT_EQ(q.shear_couple, p.shear_couple);
}

// Switches remove exactly their terms.
TEST(RackSpan, EffectSwitches) {
  Effects fx = all_effects();
  fx.body_axial = false;
  fx.body_shear = false;
  fx.couple_term = false;
  RackSpanCompliance bare(seed_rack(), kAlpha14, fx);
  const auto p = bare.parts(0.7, 0.08, 1.3, 0.07);
  EXPECT_EQ(p.axial, 0.0);
  EXPECT_EQ(p.shear, 0.0);
  EXPECT_EQ(p.shear_couple, 0.0);
  EXPECT_EQ(p.couple, 0.0);
  EXPECT_EQ(p.coupling, 0.0);
  // Only vertical bending is left: sin^2 a0 times the Gere deflection
  // b x (l^2 - b^2 - x^2)/(6 EI l) at x = 0.7 for a load at 1.3 (b = 1.1).
  const double EI = 210e9 * seed_rack().section.second_moment, l = 2.4, b = 1.1, x = 0.7;
  const double s = std::sin(kAlpha14);
  EXPECT_NEAR(p.total(), s * s * b * x * (l * l - b * b - x * x) / (6 * EI * l), 1e-12 * p.total());
  // The contact height no longer matters.
  EXPECT_EQ(bare.influence(0.7, 0.08, 1.3, 0.07), bare.influence(0.7, 0.5, 1.3, -0.2));
}

// Axial: pin-roller is softer than pin-pin by c^2 a^2/(EA l) at a single load.
TEST(RackSpan, AxialPinPinVersusPinRoller) {
  RackSpanCompliance pp(seed_rack(Supports::kPinPin), kAlpha14, all_effects());
  RackSpanCompliance pr(seed_rack(Supports::kPinRoller), kAlpha14, all_effects());
  const double EA = 210e9 * seed_rack().section.area, c = std::cos(kAlpha14), l = 2.4;
  for (double a : {0.0, 0.5, 1.2, 2.4}) {
    EXPECT_NEAR(pr.self(a, 0.08) - pp.self(a, 0.08), c * c * a * a / (EA * l), 1e-9 * pr.self(1.2, 0.08));
    EXPECT_NEAR(pp.parts(a, 0.08, a, 0.08).axial, c * c * a * (l - a) / (EA * l), 1e-20);
    EXPECT_NEAR(pr.parts(a, 0.08, a, 0.08).axial, c * c * a / EA, 1e-20);
  }
}

// A contact exactly at a hinge: the vertical, coupling, axial (pin-pin) and
// shear-force terms vanish; the couple terms remain:
// c^2 e^2 (l/(3 EI) + 1.2/(G A l)) (rotation under an end couple, l/(3EI)).
TEST(RackSpan, ContactAtHingeKeepsTheCoupleTerm) {
  const RackSpec rack = seed_rack();
  RackSpanCompliance body(rack, kAlpha14, all_effects());
  const double e = 0.08, l = 2.4, c = std::cos(kAlpha14);
  const double EI = 210e9 * rack.section.second_moment, GA = 210e9 / 2.6 * rack.section.area;
  for (double a : {0.0, l}) {
    const auto p = body.parts(a, e, a, e);
    EXPECT_EQ(p.vertical, 0.0);
    EXPECT_NEAR(p.coupling, 0.0, 1e-12 * p.total());  // round-off only
    EXPECT_EQ(p.axial, 0.0);
    EXPECT_EQ(p.shear, 0.0);
    EXPECT_NEAR(p.total(), c * c * e * e * (l / (3 * EI) + 1.2 / (GA * l)), 1e-12 * p.total());
  }
  EXPECT_EQ(body.self(0.0, 0.0), 0.0);  // no height, no compliance at a hinge
}

// Short and long spans: finite and positive at the hinges and midspan.
TEST(RackSpan, ExtremeSpansFiniteAndPositive) {
  for (double l : {0.2, 10.0}) {
    for (Supports sup : {Supports::kPinPin, Supports::kPinRoller}) {
      RackSpanCompliance body(rectangular_rack(l, 0.06, 0.0755, sup), kAlpha14, all_effects());
      for (double a : {0.0, l / 2, l}) {
        const double c = body.self(a, 0.08);
        EXPECT_TRUE(std::isfinite(c));
        EXPECT_GT(c, 0.0) << "l = " << l << ", a = " << a;
      }
      EXPECT_TRUE(std::isfinite(body.influence(0.0, 0.08, l, 0.07)));
    }
  }
  // Midspan vertical bending grows as l^3: 10 m vs 0.2 m.
  RackSpanCompliance short_body(rectangular_rack(0.2, 0.06, 0.0755, Supports::kPinPin), kAlpha14, all_effects());
  RackSpanCompliance long_body(rectangular_rack(10.0, 0.06, 0.0755, Supports::kPinPin), kAlpha14, all_effects());
  EXPECT_NEAR(long_body.parts(5.0, 0.08, 5.0, 0.08).vertical / short_body.parts(0.1, 0.08, 0.1, 0.08).vertical,
              std::pow(50.0, 3), 1e-9 * std::pow(50.0, 3));
}

TEST(RackSpan, RejectsBadInput) {
  RackSpanCompliance body(seed_rack(), kAlpha14, all_effects());
  EXPECT_THROW((void)body.self(-0.01, 0.08), std::invalid_argument);
  EXPECT_THROW((void)body.self(2.41, 0.08), std::invalid_argument);
  EXPECT_THROW((void)body.self(std::nan(""), 0.08), std::invalid_argument);
  EXPECT_THROW((void)body.influence(1.0, std::nan(""), 1.0, 0.08), std::invalid_argument);
  // A rounding error of a = x - k*span is clamped to the hinge.
  EXPECT_EQ(body.self(-1e-12, 0.08), body.self(0.0, 0.08));
  EXPECT_EQ(body.self(2.4 + 1e-12, 0.08), body.self(2.4, 0.08));

  RackSpec bad = seed_rack();
  bad.span = 0.0;
  EXPECT_THROW(RackSpanCompliance(bad, kAlpha14, all_effects()), std::invalid_argument);
  bad = seed_rack();
  bad.section.second_moment = 0.0;
  EXPECT_THROW(RackSpanCompliance(bad, kAlpha14, all_effects()), std::invalid_argument);
  bad = seed_rack();
  bad.section.shear_area = 0.0;
  EXPECT_THROW(RackSpanCompliance(bad, kAlpha14, all_effects()), std::invalid_argument);
  Effects no_shear = all_effects();
  no_shear.body_shear = false;
  EXPECT_NO_THROW(RackSpanCompliance(bad, kAlpha14, no_shear));  // kA unused
  bad = seed_rack();
  bad.section.area = -1.0;
  EXPECT_THROW(RackSpanCompliance(bad, kAlpha14, all_effects()), std::invalid_argument);
  EXPECT_THROW(RackSpanCompliance(seed_rack(), 0.0, all_effects()), std::invalid_argument);
  try {
    (void)body.self(3.0, 0.08);
    FAIL() << "no throw";
  } catch (const std::invalid_argument& err) {
    EXPECT_NE(std::string(err.what()).find("outside the span"), std::string::npos) << err.what();
  }
}
