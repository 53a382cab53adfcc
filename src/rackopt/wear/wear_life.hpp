// Deterministic Archard wear life of a rack drive (docs/models/wear.md, docs/models/mesh.md).
//
// Both flanks are discretised along the path of contact: point i of each
// member is the material point that meets the other member at LOA coordinate
// s_i, s_start <= s_i <= s_end (wear.profile_points points). A "pass" is one
// mesh of a tooth pair: the contact sweeps once through the whole path. Per
// pass, a flank point at s receives (Flodin & Andersson 1997, docs/models/wear.md)
//   pinion: dh = K/H(h) <w> |s - s_P| / s,   rack: dh = K/H(h) <w> |s - s_P| / s_P,
// where H(h) is the hardness at the depth already worn and <w> is the load per
// unit width of the pair when the contact passes the point, averaged over the
// Hertz band with the elliptic pressure weight (so load jumps at the zone
// transitions are seen through the contact band, not as points).
// One more flank point, the peak probe, sits at the largest unworn pass
// load between the profile points next to the point that fails first, so a
// wear peak narrower than the point spacing is not missed (docs/models/wear.md,
// "Default: 240 points").
// The pair loads come from the tooth models' local compliances with a rigid
// rack body and unilateral contact on the worn profiles (docs/models/mesh.md).
// docs/models/wear.md has the equations, the choices and the measured cost.
//
// Example:
//   Drive drive = load_problem("problems/ship_lift.yaml");
//   drive.wear.coefficient = 3e-6; ...; drive.duty.rack_meshes_per_year = 4000;
//   WearModel model(drive);              // geometry, compliance tables, hardness
//   WearLifeResult r = model.life();     // nominal drive
//   WearLifeResult r2 = model.life({.wear_coefficient_scale = 1.3, .contact_ratio = 1.45});
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rackopt/core/drive.hpp"
#include "rackopt/geometry/mesh_geometry.hpp"

namespace rackopt {

// One Monte Carlo realisation; the defaults give the drive's nominal values.
struct WearSample {
  double wear_coefficient_scale = 1;  // multiplies wear.coefficient (> 0)
  double force_scale = 1;             // multiplies load.force (> 0)
  double surface_hardness_scale = 1;  // multiplies both members' whole hardness profiles (> 0)
  // Empty = nominal. Otherwise the contact ratio the sample starts from (any
  // finite value, 0 included: "not sampled" is only the empty optional): the path
  // keeps its pinion-tip end s_end and starts at s_end - eps p_b, i.e. the
  // rack datum sits at the clearance that puts the rack tip there
  // (docs/models/geometry.md: Delta = (eps_nominal - eps) p_b sin a0 for a start
  // limited by the rack tip). Below max(1, wear.min_contact_ratio) the sample
  // fails at once (life 0, criterion "initial_contact_ratio"); above the largest
  // contact ratio this pair can have (zero clearance, interference limits) it
  // fails at once with "contact_ratio_above_max" (the wear paper's eq. 14 corrected,
  // docs/models/reliability.md: reliability needs [eps] <= eps <= eps_max).
  std::optional<double> contact_ratio;
};

// Wear depth along one member's active flank.
struct WearProfile {
  std::vector<double> s;         // LOA coordinate where the point meets the other member [m]
  std::vector<double> position;  // distance along the flank from the member's lowest active point
                                 // (pinion: start of the active profile, involute arc length
                                 // (s^2 - s_start^2)/(2 r_b); rack: the point that meets the
                                 // pinion tip, (s_end - s) tan a0) [m]
  std::vector<double> radius_or_height;  // pinion: radius sqrt(r_b^2 + s^2); rack: height above the datum [m]
  std::vector<double> depth;     // wear depth (or wear per pass, see initial_wear_per_pass) [m]
};

struct WearSnapshot {
  double fraction = 0;       // of the life
  double cycles = 0;         // rack passes
  double years = 0;
  double contact_ratio = 0;  // loaded contact ratio at that time
  WearProfile pinion, rack;
};

struct WearLifeResult {
  double life_cycles = 0;         // rack passes (load cycles of a rack flank point) to failure
  double life_pinion_cycles = 0;  // load cycles of a pinion flank point at that time
  double life_years = 0;          // life_cycles / duty.rack_meshes_per_year (0 when no duty given)
  // "max_depth" | "case_depth" | "contact_ratio" (loaded contact ratio fell to
  // wear.min_contact_ratio) | "initial_contact_ratio" | "contact_ratio_above_max".
  std::string criterion;
  std::string reason;             // one sentence for people
  Member limiting_member = Member::kRack;  // member whose depth ended it (rack for contact-ratio ends)
  double initial_contact_ratio = 0;
  double final_contact_ratio = 0;  // loaded contact ratio on the worn profiles (= initial without update)
  WearProfile pinion, rack;        // depth at the end of life
  std::vector<WearSnapshot> snapshots;  // 25, 50, 75, 100 % of the life
  double max_depth = 0;            // deepest wear at the end [m]
  Member max_depth_member = Member::kRack;
  double max_depth_s = 0;          // its LOA coordinate [m]
  double max_depth_position = 0;   // its position along that member's flank [m]
  std::vector<std::string> warnings;  // hardness data clamped, duty not given, ...
  int blocks = 0;                  // blocks of passes integrated
  long load_solves = 0;            // load-sharing solves (one per mesh position sampled)
  double seconds = 0;              // wall time of this call (the only non-deterministic field)
};

// Fidelity switches that are not problem keys (tests and accuracy studies).
struct WearOptions {
  // Average the pair load over the Hertz band (true) or take it at the
  // point's own contact position (false: the plain pointwise law, whose
  // closed forms are exact).
  bool hertz_band = true;
  // Mesh positions sampled per unit of path length, relative to the profile
  // point spacing (2 = twice as fine as the profile points).
  double positions_per_point = 2.0;
  // From this many profile points on, the mesh positions are no finer than
  // the profile points; below it there are at most this many positions over
  // the path, and never more than positions_per_point per point (so 120 and
  // fewer points keep 2): the effective rate is
  // min(positions_per_point, max(1, positions_cap / profile_points)). The
  // band weights and the pair compliances cost in proportion to the
  // positions, and at 240 points the finer positions change the ship lift's
  // lives by < 1e-5 (docs/accuracy.md, "Compliance tables and mesh positions
  // per point"). A huge cap keeps positions_per_point everywhere.
  double positions_cap = 240;
  // Build the nominal path's start (path, unworn load sharing, band weights)
  // once per model and start every life without a sampled contact ratio from
  // it (true), or rebuild it for every life (false: the reference the tests
  // compare the reuse with, bit for bit).
  bool reuse_nominal_start = true;
  // Intervals of the tooth compliance tables (pinion side against s, rack
  // side against contact height), linear between nodes. Their construction
  // is a fixed cost of every model, i.e. of every design of a study
  // (docs/accuracy.md, "Compliance tables and mesh positions per point").
  int compliance_intervals = 256;
  // Cells of each member's hardness integral G(h) = integral of H over
  // [0, limit depth] (H linear in each cell, G inverted exactly per cell).
  // Tabulating H is a fixed cost of every model; the integral's relative
  // error is about H'' dh^2 / (12 H), below 1e-9 for the shipped profiles.
  int hardness_cells = 2048;
  // A life read for its life only (Detail::kLifeOnly) without the profile
  // update, where no depth can pass a member's measured hardness data before
  // its limit (so no warning needs the depths), is decided by the first
  // point to reach its limit and that point's neighbours. With this on, a point's band weights are built only
  // when an upper bound of its wear rate (the largest pair load over its
  // band times its sliding) could make it that point; the life, criterion,
  // limiting member and reason are the same bits as with every point's
  // weights (false: every point's, the reference the tests compare with).
  bool bounded_life_search = true;
  // With the profile update: integrate each block with Heun's
  // predictor-corrector (the mean of the rates at the block's start and at
  // its predicted end: second order in block_fraction, two load-sharing
  // solves a block) or with the rates of its start alone (false: first
  // order, one solve a block; the reference the convergence tests compare
  // with).
  bool heun_blocks = true;
  // With the profile update: add to the pass loads the corner the straight
  // lines between load samples cut where a pair opens or closes between two
  // mesh positions (true; docs/models/wear.md, "Load seen by a point"), or
  // not (false: first order in the spacing; the reference the convergence
  // tests compare with).
  bool transition_corrections = true;
};

class WearModel {
 public:
  // Builds the geometry, the tooth compliance tables over the path and the
  // hardness integrals. Throws InputError for a wear or duty spec that cannot
  // be used (K <= 0 "not configured", max_depth <= 0, profile_points < 3,
  // block_fraction outside (0, 1], negative duty, load <= 0, bad hardness
  // profiles) and DesignError for an impossible geometry (build_mesh_geometry).
  explicit WearModel(const Drive& drive, WearOptions options = {});
  ~WearModel();
  WearModel(WearModel&&) noexcept;
  WearModel& operator=(WearModel&&) noexcept;

  // Wear life of one realisation. const, thread-safe (the one shared mutable
  // state, the nominal start built on first use, is built under
  // std::call_once) and deterministic. Throws InputError for a non-positive or
  // non-finite scale or a non-finite contact ratio; every other outcome is a
  // finite result (contact ratio out of range: life 0 with the reason).
  WearLifeResult life(const WearSample& sample = {}) const;
  // What a life fills in: everything; everything but the snapshots (empty;
  // the other fields are the same bits); or the life alone, for callers that
  // read only the life, its criterion and its warnings (the reliability's
  // table, quantile and sample lives, the metrics' nominal life):
  // life_cycles, life_pinion_cycles, life_years, criterion, reason,
  // limiting_member, the contact ratios, warnings, blocks and load_solves are
  // the same bits as the full result's, while the profiles and the deepest
  // wear may be left empty (they are without the profile update when no
  // depth can pass the measured hardness data: WearOptions::bounded_life_search).
  enum class Detail { kFull, kNoSnapshots, kLifeOnly };
  WearLifeResult life(const WearSample& sample, Detail detail) const;

  // Wear per pass of the unworn flanks [m per own pass] along both profiles
  // (depth field), for plots and checks.
  struct PassWear {
    WearProfile pinion, rack;
    std::vector<double> load_per_width;  // <w> at the rack points (band-averaged pair load) [N/m]
    double contact_ratio = 0;
  };
  PassWear initial_wear_per_pass(const WearSample& sample = {}) const;

  const MeshGeometry& geometry() const;
  double nominal_contact_ratio() const;
  // Largest contact ratio a sample may start from (zero clearance, with the
  // interference/undercut limit when effects.interference_limit is on).
  double max_contact_ratio() const;
  // Warnings of the model itself (geometry).
  const std::vector<std::string>& warnings() const;

 private:
  struct Impl;
  std::unique_ptr<const Impl> impl_;
};

}  // namespace rackopt
