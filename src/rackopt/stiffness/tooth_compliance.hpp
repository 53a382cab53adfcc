// Compliance of one tooth under a unit normal load, split by strain energy.
#pragma once

namespace rackopt {

// [m/N] each; a component switched off is 0.
struct ToothCompliance {
  double bending = 0.0;
  double shear = 0.0;
  double axial = 0.0;
  double total() const { return bending + shear + axial; }
};

// Material removed by a spall from one flank over a band of tooth height,
// in the member's own terms (docs/models/tooth.md). depth is measured normal to the
// flank (into the half-thickness), width across the face.
struct SpallBand {
  double low = 0.0;    // pinion: lower edge radius [m]; rack: lower edge height above the root line [m]
  double high = 0.0;   // pinion: upper edge radius; rack: upper edge height above the root line
  double width = 0.0;  // w_s [m]
  double depth = 0.0;  // h_s [m]
};

// Checks what any band must satisfy whatever the tooth: width and depth >= 0
// and low <= high; throws InputError otherwise. Returns false when the band
// removes nothing (zero width or depth), so callers can skip the tooth checks.
bool spall_band_removes_material(const SpallBand& band);

}  // namespace rackopt
