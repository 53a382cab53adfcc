#include "rackopt/wear/hardness.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "rackopt/core/error.hpp"

namespace rackopt {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

[[noreturn]] void fail(const std::string& key, const std::string& what) {
  throw InputError(SourceMark{}, key, what);
}

std::string hb(double pa) {
  std::ostringstream o;
  o << pa / kPaPerHB << " HB";
  return o.str();
}

}  // namespace

HardnessModel::HardnessModel(const HardnessProfile& p, std::string key) : kind_(p.kind) {
  using K = HardnessProfile::Kind;
  if (!std::isfinite(p.core) || p.core < 0) fail(key + ".core", "core hardness must be >= 0 and finite");
  switch (kind_) {
    case K::kConstant: {
      if (!(p.surface > 0) || !std::isfinite(p.surface))
        fail(key + ".surface", "surface hardness must be positive and finite");
      surface_ = core_ = p.surface;
      first_clamped_depth_ = kInf;
      break;
    }
    case K::kPolynomial: {
      if (p.coefficients.empty()) fail(key + ".coefficients", "a polynomial profile needs coefficients");
      for (double c : p.coefficients)
        if (!std::isfinite(c)) fail(key + ".coefficients", "coefficients must be finite");
      if (!(p.valid_depth > 0) || !std::isfinite(p.valid_depth))
        fail(key + ".valid_depth", "the deepest measured depth must be positive (the fit is not used beyond it)");
      coefficients_ = p.coefficients;
      valid_depth_ = p.valid_depth;
      core_ = p.core > 0 ? p.core : polynomial(valid_depth_);
      if (!(core_ > 0)) {
        fail(key + ".core", "the fit is " + hb(polynomial(valid_depth_)) +
                                " at its valid depth: give a positive core hardness to clamp to");
      }
      // First depth where the fit drops below the core (scan, then bisect).
      first_clamped_depth_ = valid_depth_;
      const int n = 2000;
      double prev = 0;
      for (int i = 0; i <= n; ++i) {
        const double h = valid_depth_ * i / n;
        if (polynomial(h) < core_) {
          double lo = prev, hi = h;
          if (i == 0) {
            lo = hi = 0;
          }
          for (int it = 0; it < 60 && hi - lo > 0; ++it) {
            const double mid = 0.5 * (lo + hi);
            (polynomial(mid) < core_ ? hi : lo) = mid;
          }
          first_clamped_depth_ = hi;
          break;
        }
        prev = h;
      }
      surface_ = evaluate(0).hardness;
      break;
    }
    case K::kTable: {
      if (p.depths.empty()) fail(key + ".depths", "a table profile needs at least one point");
      if (p.depths.size() != p.values.size()) fail(key + ".values", "depths and values must have the same length");
      for (std::size_t i = 0; i < p.depths.size(); ++i) {
        if (!std::isfinite(p.depths[i]) || p.depths[i] < 0) fail(key + ".depths", "depths must be >= 0 and finite");
        if (i > 0 && !(p.depths[i] > p.depths[i - 1]))
          fail(key + ".depths", "depths must be strictly ascending");
        if (!(p.values[i] > 0) || !std::isfinite(p.values[i]))
          fail(key + ".values", "hardness values must be positive and finite");
      }
      depths_ = p.depths;
      values_ = p.values;
      core_ = p.core > 0 ? p.core : values_.back();
      first_clamped_depth_ = depths_.back();
      for (std::size_t i = 0; i < values_.size(); ++i) {
        if (values_[i] < core_) {
          if (i == 0) {
            first_clamped_depth_ = 0;
          } else {
            // Linear segment crosses the core between points i-1 and i.
            const double t = (values_[i - 1] - core_) / (values_[i - 1] - values_[i]);
            first_clamped_depth_ = depths_[i - 1] + t * (depths_[i] - depths_[i - 1]);
          }
          break;
        }
      }
      surface_ = evaluate(0).hardness;
      break;
    }
    case K::kCaseHardened: {
      if (!(p.surface > 0) || !std::isfinite(p.surface))
        fail(key + ".surface", "surface hardness must be positive and finite");
      if (!(p.core > 0)) fail(key + ".core", "a case-hardened profile needs a positive core hardness");
      if (!(p.core < p.surface))
        fail(key + ".core", "core hardness " + hb(p.core) + " must be below the surface hardness " + hb(p.surface));
      if (!(p.case_depth > 0) || !std::isfinite(p.case_depth))
        fail(key + ".case_depth", "the hardening depth must be positive and finite");
      if (!(p.exponent > 0) || !std::isfinite(p.exponent)) fail(key + ".exponent", "the exponent must be positive");
      const double lim = p.limit > 0 ? p.limit : 0.8 * p.surface;
      if (!(lim > p.core && lim < p.surface)) {
        fail(key + ".limit", "the limit hardness at the hardening depth (" + hb(lim) +
                                 (p.limit > 0 ? "" : ", default 0.8 x surface") +
                                 ") must lie strictly between the core " + hb(p.core) + " and the surface " +
                                 hb(p.surface));
      }
      surface_ = p.surface;
      core_ = p.core;
      exponent_ = p.exponent;
      delta_ = p.case_depth / std::pow(std::log((surface_ - core_) / (lim - core_)), 1.0 / exponent_);
      first_clamped_depth_ = kInf;
      break;
    }
  }
  case_depth_ = p.case_depth > 0 ? p.case_depth : 0.0;
}

double HardnessModel::polynomial(double h) const {
  double v = 0;
  for (auto it = coefficients_.rbegin(); it != coefficients_.rend(); ++it) v = v * h + *it;
  return v;
}

double HardnessModel::raw_table(double h) const {
  if (h <= depths_.front()) return values_.front();
  const auto it = std::upper_bound(depths_.begin(), depths_.end(), h);
  const std::size_t i = static_cast<std::size_t>(it - depths_.begin());  // depths_[i-1] < h <= depths_[i]
  const double t = (h - depths_[i - 1]) / (depths_[i] - depths_[i - 1]);
  return values_[i - 1] + t * (values_[i] - values_[i - 1]);
}

HardnessModel::Value HardnessModel::evaluate(double depth) const {
  const double h = std::max(depth, 0.0);
  using K = HardnessProfile::Kind;
  switch (kind_) {
    case K::kConstant:
      return {surface_, false};
    case K::kPolynomial: {
      if (h > valid_depth_) return {core_, true};
      const double v = polynomial(h);
      if (v < core_) return {core_, true};
      return {v, false};
    }
    case K::kTable: {
      if (h > depths_.back()) return {core_, true};
      const double v = raw_table(h);
      if (v < core_) return {core_, true};
      return {v, false};
    }
    case K::kCaseHardened:
      return {core_ + (surface_ - core_) * std::exp(-std::pow(h / delta_, exponent_)), false};
  }
  return {core_, true};
}

}  // namespace rackopt
